using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.IntegrationTests.Polling;

/// <summary>
/// Read, write with read-back and bit set/reset end to end over a real serial line (socat pty pair) to a reference
/// PLC served by SimulatedPlcHost. Real time, each test bounded by <see cref="SerialLineRig.Limit"/> per wait.
/// </summary>
public sealed class PollingEngineSerialTests
{
    [Fact]
    public async Task Refresh_SeveralAreas_ReturnsExactlyThePlcBytes()
    {
        var plc = SerialLineRig.Plc(2);
        var m = plc.Memory;
        (m.I[0], m.I[1], m.Q[0], m.Q[1], m.M[3], m.M[10], m.M[11]) = (0xA5, 0x3C, 0x81, 0x7E, 0x42, 0x12, 0x34);
        (m.V[100], m.V[101], m.V[102], m.V[103], m.V[2000], m.V[2001], m.V[3000], m.Q[15]) = (0xDE, 0xAD, 0xBE, 0xEF, 0x0B, 0xB8, 0x20, 0x99);
        await using var rig = await SerialLineRig.StartAsync([plc], ["IB0", "IB1", "QW0", "MB3", "MW10", "VD100", "VW2000", "V3000.5", "V3000.4", "QB15"]);

        var result = await rig.RefreshUntilAsync(r => r.FramesFailed == 0);

        result.FramesFailed.Should().Be(0);
        rig.Value(plc, "IB0").Raw.Should().Equal(0xA5);
        rig.Value(plc, "IB1").Raw.Should().Equal(0x3C);
        rig.Value(plc, "QW0").Raw.Should().Equal(0x81, 0x7E);
        rig.Value(plc, "MB3").Raw.Should().Equal(0x42);
        rig.Value(plc, "MW10").Raw.Should().Equal(0x12, 0x34);
        rig.Value(plc, "VD100").Raw.Should().Equal(0xDE, 0xAD, 0xBE, 0xEF);
        rig.Value(plc, "VW2000").Raw.Should().Equal(0x0B, 0xB8);
        rig.Value(plc, "V3000.5").AsBit.Should().BeTrue();
        rig.Value(plc, "V3000.4").AsBit.Should().BeFalse();
        rig.Value(plc, "QB15").Raw.Should().Equal(0x99);
        rig.Value(plc, "VD100").Quality.Should().Be(ValueQuality.Good);

        m.WriteDoubleWord(ProtocolArea.V, 100, 1_000_000);
        await rig.RefreshUntilAsync(r => r.FramesFailed == 0);

        rig.Value(plc, "VD100").Raw.Should().Equal(0x00, 0x0F, 0x42, 0x40);
    }

    [Fact]
    public async Task Write_WordDoubleWordAndOutputByte_ConfirmedAndHeldByThePlc()
    {
        var plc = SerialLineRig.Plc(2);
        var station = plc.Config.Station;
        await using var rig = await SerialLineRig.StartAsync([plc], ["VW200", "VD300", "QB1"]);

        var word = await rig.Bus.WriteAsync(WriteRequest.Bytes(station, PlcAddress.Parse("VW200"), [0x01, 0x2C])).WaitAsync(SerialLineRig.Limit);
        var dword = await rig.Bus.WriteAsync(WriteRequest.Bytes(station, PlcAddress.Parse("VD300"), [0x00, 0x01, 0x86, 0xA0])).WaitAsync(SerialLineRig.Limit);
        var output = await rig.Bus.WriteAsync(WriteRequest.Bytes(station, PlcAddress.Parse("QB1"), [0x5A])).WaitAsync(SerialLineRig.Limit);

        ConfirmedWrite.ReadBackOf(word).Should().Equal(0x01, 0x2C);
        ConfirmedWrite.ReadBackOf(dword).Should().Equal(0x00, 0x01, 0x86, 0xA0);
        ConfirmedWrite.ReadBackOf(output).Should().Equal(0x5A);
        plc.Memory.ReadWord(ProtocolArea.V, 200).Should().Be(300);
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 300).Should().Be(100_000);
        plc.Memory.Q[1].Should().Be(0x5A);
        rig.Value(plc, "VW200").Raw.Should().Equal(0x01, 0x2C);
    }

    [Fact]
    public async Task Write_InputByte_RefusedAsNotWritableAndMemoryUnchanged()
    {
        var plc = SerialLineRig.Plc(2);
        var station = plc.Config.Station;
        plc.Memory.I[0] = 0x5A;
        await using var rig = await SerialLineRig.StartAsync([plc], ["IB0"]);

        var viaEngine = await rig.Bus.WriteAsync(WriteRequest.Bytes(station, PlcAddress.Parse("IB0"), [0xFF])).WaitAsync(SerialLineRig.Limit);
        var viaWire = await rig.Bus.ExchangeAsync(new WriteBlockRequest(station, 0x40, ProtocolArea.I, 0, [0xFF]), default).WaitAsync(SerialLineRig.Limit);

        viaEngine.Should().BeOfType<WriteOutcome.Failed>().Which.Kind.Should().Be(WriteFailureKind.InvalidRequest);
        viaWire.Response.Should().BeOfType<ErrorResponse>().Which.Error.Should().Be(ProtocolError.NotWritable);
        plc.Memory.I[0].Should().Be(0x5A);
    }

    [Fact]
    public async Task WriteBit_SetAndResetWhileTheProgramChangesTheByte_OtherBitsUntouched()
    {
        var plc = SerialLineRig.Plc(2);
        var station = plc.Config.Station;
        var m5 = PlcAddress.Parse("M5.1");
        plc.Memory.M[5] = 0x01;
        await using var rig = await SerialLineRig.StartAsync([plc], ["M5.1", "MB5"]);

        // The PLC program owns M5.0 and the high nibble of MB5: a scan counter it rewrites between every two receive
        // interrupts, so the byte the panel last polled is always out of date when the WRITE BIT executes.
        var scans = 0;
        rig.Tap.OnReceived = () =>
        {
            var scan = Interlocked.Increment(ref scans);
            plc.Memory.M[5] = (byte)((plc.Memory.M[5] & 0x0F) | (((scan % 15) + 1) << 4));
        };
        await rig.RefreshUntilAsync(r => r.FramesFailed == 0);
        var polled = rig.Value(plc, "MB5").Raw[0];

        var set = await rig.Bus.WriteAsync(WriteRequest.Bit(station, m5, true)).WaitAsync(SerialLineRig.Limit);
        var afterSet = plc.Memory.M[5];
        var readBackAfterSet = rig.Value(plc, "MB5").Raw[0];
        var reset = await rig.Bus.WriteAsync(WriteRequest.Bit(station, m5, false)).WaitAsync(SerialLineRig.Limit);
        var afterReset = plc.Memory.M[5];

        ConfirmedWrite.ReadBackOf(set);
        ConfirmedWrite.ReadBackOf(reset);
        (afterSet & 0x0F).Should().Be(0x03, "M5.0 stays set and only M5.1 was added");
        (afterSet & 0xF0).Should().NotBe(polled & 0xF0, "the program changed the byte after the panel polled it");
        readBackAfterSet.Should().Be(afterSet, "the read-back is the whole byte as the PLC holds it");
        (afterReset & 0x0F).Should().Be(0x01, "M5.0 stays set and only M5.1 was cleared");
        (afterReset & 0xF0).Should().NotBe(0, "the program's nibble is kept");
        rig.Value(plc, "M5.1").AsBit.Should().BeFalse();
    }
}
