using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

/// <summary>Jobs written by <see cref="S7JobCodec"/> against published captures (TestKit PpiCaptures), byte for byte.</summary>
public sealed class S7JobCodecTests
{
    [Fact]
    public void Read_SevenItemsOfTheCapture_IsTheCapturedRequest()
    {
        S7Item[] items =
        [
            S7Item.Bytes(S7Area.I, 0, 2), S7Item.Bytes(S7Area.Q, 0, 1), S7Item.Bytes(S7Area.M, 0, 1), S7Item.Bytes(S7Area.M, 10, 1),
            S7Item.Bytes(S7Area.V, 100, 1), S7Item.Bytes(S7Area.V, 110, 1), S7Item.Bytes(S7Area.V, 200, 4),
        ];

        var frame = Frame(S7JobCodec.Read(0x2659, items), 0x7C);

        Hex.Format(frame).Should().Be(Hex.Format(Hex.Parse(PpiCaptures.ReadSevenItemsRequest)));
    }

    [Fact]
    public void Write_VD300_IsTheCapturedRequest()
    {
        var item = S7WriteItem.Of(S7Item.Bytes(S7Area.V, 300, 4), [0x45, 0x20, 0x80, 0x00]);

        var frame = Frame(S7JobCodec.Write(0x2734, [item]), 0x7C);

        Hex.Format(frame).Should().Be(Hex.Format(Hex.Parse(PpiCaptures.WriteVd300Request)));
    }

    [Fact]
    public void Read_Timers_IsTheCapturedRequest()
    {
        var frame = Frame(S7JobCodec.Read(0, [S7Item.Timers(32, 3)]), PpiFunctionCode.FirstRequest);

        Hex.Format(frame).Should().Be(PpiCaptures.ReadTimersRequest);
    }

    [Fact]
    public void StopAndRun_AreTheCapturedRequests()
    {
        Hex.Format(Frame(S7JobCodec.Stop(0), PpiFunctionCode.FirstRequest)).Should().Be(PpiCaptures.StopRequest);
        Hex.Format(Frame(S7JobCodec.Run(0), PpiFunctionCode.FirstRequest)).Should().Be(PpiCaptures.RunRequest);
    }

    [Fact]
    public void Write_OddBytesBeforeAnotherItem_ArePaddedAndBitsCountInBits()
    {
        S7WriteItem[] items =
        [
            S7WriteItem.Of(S7Item.Bytes(S7Area.Q, 0, 1), [0xA5]),
            S7WriteItem.Of(S7Item.Bit(S7Area.M, 3, 4), [0x01]),
        ];

        var pdu = S7JobCodec.Write(7, items);

        Hex.Format(pdu.AsSpan(36)).Should().Be("00 04 00 08 A5 00 00 03 00 01 01",
            "QB0: 8 bits and a pad; M3.4: size 03, 1 bit, no pad (last)");
        Hex.Format(pdu.AsSpan(24, 12)).Should().Be("12 0A 10 01 00 01 00 00 83 00 00 1C", "M3.4 is bit address 28");
    }

    [Fact]
    public void SetupCommunication_Offers240AndOneJobEachWay()
    {
        Hex.Format(S7JobCodec.SetupCommunication(1, 240)).Should().Be("32 01 00 00 00 01 00 08 00 00 F0 00 00 01 00 01 00 F0");
    }

    private static byte[] Frame(byte[] job, byte functionCode) =>
        PpiFrameCodec.Encode(PpiFrame.Variable(2, 0, functionCode, job));
}
