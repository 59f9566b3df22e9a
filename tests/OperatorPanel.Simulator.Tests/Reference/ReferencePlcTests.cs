using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using static OperatorPanel.Simulator.Tests.Reference.Exchange;

namespace OperatorPanel.Simulator.Tests.Reference;

public sealed class ReferencePlcTests
{
    private static ReferencePlc Plc224(int port = 0, byte writeMask = HandlerConfig.DefaultWriteMask, CpuModel model = CpuModel.Cpu224) =>
        new(new HandlerConfig(new Station(1), CpuProfiles.For(model), port, writeMask, replyDelayMs: 5));

    [Theory]
    [InlineData("<010701dl`l>", "<010701dl`m>")] //                  bad check
    [InlineData("<010701dl`l>", "<010700dl`l>")] //                  a body bit flipped
    [InlineData("<010701dl`l>", "<0107dl`l>")] //                    body shorter than 6 characters
    [InlineData("<010701dl`l>", "<0107010dl`l>")] //                 odd length
    [InlineData("<010701dl`l>", "<01070adl`l>")] //                  lowercase hex
    [InlineData("<010701dl`l>", "<010701DL`L>")] //                  hex digits where the check characters belong
    [InlineData("<010701dl`l>", "<01070107>")] //                    the v1 IDENTIFY probe
    [InlineData("<010701dl`l>", "010701dl`l>")] //                   no start character
    public void HandleFrame_FramingFault_IsSilent(string good, string bad)
    {
        var plc = Plc224();

        // The intact frame is an IDENTIFY that station 1 answers (CMD 81, STATUS 00), so the silence below is the fault's.
        var answer = plc.HandleFrame(Encoding.ASCII.GetBytes(good));
        FrameCodec.TryDecode(answer, out var reply, out _).Should().BeTrue();
        (reply.Station, reply.Sequence, reply.Command, reply.Payload[0]).Should().Be(((byte)1, (byte)7, (byte)0x81, (byte)0));

        plc.HandleFrame(Encoding.ASCII.GetBytes(bad)).Should().BeNull();
    }

    [Fact]
    public void HandleFrame_OtherStation_IsSilent() => Send(Plc224(), "02 07 01").Should().BeNull();

    [Fact]
    public void HandleFrame_OverheardReply_IsSilent() => Send(Plc224(), "01 07 81", "00").Should().BeNull();

    [Theory]
    [InlineData("01 00 0A", "", 0x05)] //                unknown command
    [InlineData("01 00 07", "53544F50", 0x05)] //        STOP in a handler generated without it
    [InlineData("01 00 08", "01", 0x04)] //              READ CHANGES without FLAGS
    [InlineData("01 00 08", "01 02", 0x06)] //           FLAGS bit 1
    [InlineData("01 00 08", "01 01", 0x07)] //           list 1 not defined
    [InlineData("01 00 08", "05 00", 0x07)] //           list 5 is never defined
    [InlineData("01 00 7F", "", 0x05)]
    [InlineData("01 00 01", "00", 0x04)] //              IDENTIFY with payload
    [InlineData("01 00 02", "00", 0x04)] //              COUNT 0
    [InlineData("01 00 02", "02 04000001", 0x04)] //     COUNT 2, one item
    [InlineData("01 00 02", "01 04000000", 0x04)] //     LENGTH 0
    [InlineData("01 00 02", "01 09000001", 0x02)] //     area 09
    [InlineData("01 00 02", "01 04200001", 0x02)] //     VB8192 on a 224
    [InlineData("01 00 02", "01 05022502", 0x02)] //     SMB549 + 2 > 550
    [InlineData("01 00 02", "02 04000040 04000033", 0x04)] // 64 + 51 = 115 > 114 for two items
    [InlineData("01 00 03", "04000077" + "00", 0x04)] // WRITE LENGTH 119
    [InlineData("01 00 03", "04000002 00", 0x04)] //     body does not match LENGTH
    [InlineData("01 00 03", "01000001 00", 0x03)] //     I is never writable
    [InlineData("01 00 03", "05001D02 0000", 0x03)] //   SMB29-30
    [InlineData("01 00 04", "03000008 01", 0x06)] //     BIT 8
    [InlineData("01 00 04", "03000000 02", 0x06)] //     VALUE 2
    [InlineData("01 00 04", "03002000 01", 0x02)] //     MB32
    [InlineData("01 00 04", "03000000", 0x04)] //      body 7 bytes
    public void HandleFrame_RuleBroken_RepliesWithTheErrorCode(string head, string payload, byte status)
    {
        var reply = Send(Plc224(), head, payload) ?? throw new Xunit.Sdk.XunitException("the station stayed silent; an error reply was due");

        reply.Command.Should().Be((byte)(Exchange.Hex(head)[2] | 0x80));
        reply.Payload.Should().Equal(status);
    }

    [Theory]
    [InlineData(0, 30)]
    [InlineData(0, 34)]
    [InlineData(0, 86)]
    [InlineData(0, 94)]
    [InlineData(1, 130)]
    [InlineData(1, 186)]
    [InlineData(1, 194)]
    [InlineData(1, 34)]
    [InlineData(0, 0)]
    [InlineData(1, 29)]
    public void HandleFrame_WriteToProtectedSmByte_Replies03(int port, int smByte)
    {
        var plc = Plc224(port, model: CpuModel.Cpu226);

        Send(plc, "01 00 03", $"05{smByte:X4}01 00")!.Payload.Should().Equal(0x03);
        Send(plc, "01 00 04", $"05{smByte:X4}00 01")!.Payload.Should().Equal(0x03);
    }

    [Theory]
    [InlineData(0, 130)]
    [InlineData(0, 186)]
    [InlineData(1, 30)]
    [InlineData(1, 86)]
    [InlineData(0, 95)]
    public void HandleFrame_WriteToOtherPortsSmByte_Succeeds(int port, int smByte)
    {
        var plc = Plc224(port, model: CpuModel.Cpu226);

        Send(plc, "01 00 03", $"05{smByte:X4}01 5A")!.Payload.Should().Equal(0x00, 0x5A);
        plc.Memory.SM[smByte].Should().Be(0x5A);
    }

    [Fact]
    public void HandleFrame_BlockTouchingOneProtectedByte_IsRefusedWhole()
    {
        var plc = Plc224();

        Send(plc, "01 00 03", "05005502 1122")!.Payload.Should().Equal(0x03); // SMB85-86
        plc.Memory.SM[85].Should().Be(0);
    }

    [Theory]
    [InlineData(0x38, "02", 0x03)] // Q not in mask
    [InlineData(0x38, "03", 0x00)]
    [InlineData(0x04, "04", 0x03)] // V not in mask
    [InlineData(0x04, "02", 0x00)]
    public void HandleFrame_WriteMask_DecidesWritability(byte mask, string area, byte status)
    {
        Send(Plc224(writeMask: mask), "01 00 03", area + "000001 01")!.Payload[0].Should().Be(status);
    }

    [Fact]
    public void HandleFrame_WriteBitSetAndReset_ChangesOnlyThatBitAndReadsBackTheByte()
    {
        var plc = Plc224();
        plc.Memory.M[4] = 0b1010_0001;

        Send(plc, "01 01 04", "03000402 01")!.Payload.Should().Equal(0x00, 0b1010_0101);
        Send(plc, "01 02 04", "03000407 00")!.Payload.Should().Equal(0x00, 0b0010_0101);
        Send(plc, "01 03 04", "03000407 00")!.Payload.Should().Equal(0x00, 0b0010_0101); // idempotent
        plc.Memory.M[4].Should().Be(0b0010_0101);
    }

    [Fact]
    public void HandleFrame_WriteThenRead_ReadsBackWhatWasWritten()
    {
        var plc = Plc224();

        Send(plc, "01 01 03", "04006404 00000457")!.Payload.Should().Equal(0x00, 0x00, 0x00, 0x04, 0x57);
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 100).Should().Be(0x457);
        Send(plc, "01 02 02", "02 04006404 04006302")!.Payload.Should().Equal(0x00, 0x00, 0x00, 0x04, 0x57, 0x00, 0x00);
    }

    [Theory]
    [InlineData(1, 116, 0x00)]
    [InlineData(1, 117, 0x04)] // 2 x 117 + 4 x 1 = 238 > 237
    [InlineData(20, 78, 0x00)]
    [InlineData(20, 79, 0x04)] // 158 + 80 = 238 > 237
    [InlineData(21, 21, 0x04)] // COUNT above 20
    public void HandleFrame_ReadAgainstTheTwoDPlusFourNRule_AnswersUpToTheLimitAndRefusesPastIt(int items, int totalLength, byte status)
    {
        // V blocks 128 bytes apart; the first takes what the others (1 byte each) leave of the total.
        var payload = $"{items:X2}" + string.Concat(Enumerable.Range(0, items).Select(i => $"04{i * 128:X4}{(i == 0 ? totalLength - items + 1 : 1):X2}"));

        var reply = Send(Plc224(), "01 00 02", payload)!;

        reply.Payload[0].Should().Be(status);
        reply.Payload.Length.Should().Be(status == 0x00 ? 1 + totalLength : 1);
    }

    [Fact]
    public void HandleFrame_Reply_EchoesStationSequenceAndCommandWithBit7()
    {
        var reply = Send(Plc224(), "01 C3 02", "01 02000002")!;

        (reply.Station, reply.Sequence, reply.Command).Should().Be(((byte)1, (byte)0xC3, (byte)0x82));
    }

    [Theory]
    [InlineData(CpuModel.Cpu221, 1, 0x60, 0x0654)] // V_FIRST = 2048 - 428
    [InlineData(CpuModel.Cpu222, 2, 0x00, 0x0654)]
    [InlineData(CpuModel.Cpu224, 3, 0x20, 0x1E54)] //  8192 - 428
    [InlineData(CpuModel.Cpu224XP, 4, 0x20, 0x2654)] // 10240 - 428
    [InlineData(CpuModel.Cpu226, 5, 0x90, 0x2654)]
    public void HandleFrame_Identify_ReportsHandlerCpuPortAndVRange(CpuModel model, byte code, byte smb6, int vFirst)
    {
        var plc = new ReferencePlc(new HandlerConfig(new Station(1), CpuProfiles.For(model), 0, 0x1C, replyDelayMs: 7));
        plc.CompleteScan(4);
        plc.CompleteScan(9);
        plc.CompleteScan(2);

        var reply = Send(plc, "01 07 01")!;

        // protocol 02, revision 01, CPU, Current, mask, MAX_READ_DATA 116, 7 ms, SMB6, RUN, scans 2/2/9 ms; then port 0,
        // V_FIRST, V_BYTES 428 (256 buffer + 52 work bytes + 120 copy bytes), FEATURES 06 (copies and 09, no STOP), COPY_BYTES 120
        reply.Payload.Should().Equal(
            0x00, 0x02, 0x01, code, 0x01, 0x1C, 0x74, 0x07, smb6, 0x01, 0x00, 0x02, 0x00, 0x02, 0x00, 0x09,
            0x00, (byte)(vFirst >> 8), (byte)vFirst, 0x01, 0xAC, 0x06, 0x78);
    }

    [Fact]
    public void HandleFrame_IdentifyEarlyCpu_ReportsRevision0()
    {
        var plc = new ReferencePlc(new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224, CpuRevision.Early)));

        Send(plc, "01 07 01")!.Payload[4].Should().Be(0x00);
    }

    [Fact]
    public void HandleFrame_PlcInStop_IsSilent()
    {
        var plc = Plc224();
        plc.Mode = OperatingMode.Stop;

        Send(plc, "01 07 01").Should().BeNull();
    }

    [Fact]
    public void HandleFrame_ModeSwitchAtTerm_IsSilentAndClearsSm07()
    {
        var plc = Plc224();
        plc.Switch = ModeSwitch.Term;

        Send(plc, "01 07 01").Should().BeNull();
        plc.Memory.GetBit(ProtocolArea.SM, 0, 7).Should().BeFalse();
    }

    [Fact]
    public void HandlerConfig_WriteMaskWithI_Throws()
    {
        var act = () => new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224), writeMask: 0x02);

        act.Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void HandlerConfig_Port1OnSinglePortCpu_Throws()
    {
        var act = () => new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224), port: 1);

        act.Should().Throw<ArgumentOutOfRangeException>();
    }
}
