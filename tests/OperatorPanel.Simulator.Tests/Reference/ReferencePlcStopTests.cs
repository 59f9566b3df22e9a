using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using static OperatorPanel.Simulator.Tests.Reference.Exchange;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>07 STOP on the reference model (docs/protocol-v2.md, "07 STOP").</summary>
public sealed class ReferencePlcStopTests
{
    private const string Stop = "53544F50";

    private static ReferencePlc Plc(bool allowStop, int copyBytes = HandlerMemory.DefaultCopyBytes) =>
        new(new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224), allowStop: allowStop, copyBytes: copyBytes));

    [Fact]
    public void Stop_Enabled_RepliesOkThenTheCpuIsInStopAndSilent()
    {
        var plc = Plc(allowStop: true);
        Send(plc, "01 01 05", "01 01 03000201");

        Send(plc, "01 02 07", Stop)!.Payload.Should().Equal(0x00);

        plc.Mode.Should().Be(OperatingMode.Stop);
        Send(plc, "01 03 01").Should().BeNull("in STOP the port speaks PPI");
        plc.Mode = OperatingMode.Run;
        Send(plc, "01 04 06", "01")!.Payload.Should().Equal(new byte[] { 0x07 }, "STOP cleared the lists");
    }

    [Fact]
    public void Stop_NotGenerated_IsAnUnknownCommandAndTheCpuRuns()
    {
        var plc = Plc(allowStop: false);

        Send(plc, "01 01 07", Stop)!.Payload.Should().Equal(0x05);

        plc.Mode.Should().Be(OperatingMode.Run);
    }

    [Theory]
    [InlineData("53544F", 0x04)]
    [InlineData("53544F5000", 0x04)]
    [InlineData("53544F51", 0x06)]
    public void Stop_WrongPayload_IsRefusedAndTheCpuRuns(string payload, byte status)
    {
        var plc = Plc(allowStop: true);

        Send(plc, "01 01 07", payload)!.Payload.Should().Equal(status);

        plc.Mode.Should().Be(OperatingMode.Run);
    }

    [Theory]
    [InlineData(true, 120, 0x07, 428)]
    [InlineData(false, 120, 0x06, 428)]
    [InlineData(true, 0, 0x05, 308)]
    [InlineData(false, 255, 0x06, 563)]
    public void Identify_ReportsFeaturesCopyBytesAndTheVRangeTheyTake(bool allowStop, int copyBytes, byte features, int vBytes)
    {
        var plc = Plc(allowStop, copyBytes);

        var payload = Send(plc, "01 01 01")!.Payload;

        (payload[21], payload[22]).Should().Be((features, (byte)copyBytes));
        ((payload[19] << 8) | payload[20]).Should().Be(vBytes);
        ((payload[17] << 8) | payload[18]).Should().Be(plc.Config.BufferStart).And.Be((8192 - vBytes) & ~1);
    }
}
