using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Writes;
using OperatorPanel.IntegrationTests.Polling;
using OperatorPanel.Simulator.Hosting;

namespace OperatorPanel.IntegrationTests.V3;

/// <summary>The v3 link over a real serial pair (socat ptys, System.IO.Ports on both ends) to reference v3 stations.</summary>
public sealed class V3SerialTests
{
    [Fact]
    public async Task Refresh_OverASocatPtyPair_ListReadGoodWriteConfirmedChangeSeen()
    {
        var station = V3Rig.Handler(2);
        station.Memory.V[100] = 0x42;
        (station.Memory.M[4], station.Memory.M[5]) = (0x12, 0x34);
        var line = new V3ReferenceLine([station]) { CharacterTime = TimeSpan.FromMilliseconds(10.0 / 19.2) };
        await using var rig = await SerialLineRig.StartV3Async(line, ["VB100", "MW4", "Q0.3"]);

        await rig.RefreshUntilAsync(r => rig.Value(new Station(2), "MW4").Quality == ValueQuality.Good);
        var write = await rig.Bus.WriteAsync(WriteRequest.Bytes(new Station(2), PlcAddress.Parse("VB100"), [0x43])).WaitAsync(SerialLineRig.Limit);
        station.Memory.M[5] = 0x35;
        await rig.RefreshUntilAsync(r => rig.Value(new Station(2), "MW4").Raw.SequenceEqual(new byte[] { 0x12, 0x35 }));

        write.Should().BeOfType<WriteOutcome.Confirmed>();
        Convert.ToHexString(rig.Value(new Station(2), "MW4").Raw.AsSpan()).Should().Be("1235");
        rig.Value(new Station(2), "MW4").Quality.Should().Be(ValueQuality.Good);
        Convert.ToHexString(rig.Value(new Station(2), "VB100").Raw.AsSpan()).Should().Be("43");
        station.Memory.V[100].Should().Be(0x43);
    }
}
