using System.Collections.Immutable;
using System.Text;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

public sealed class FrameCodecTests
{
    [Theory]
    //           ST SQ CM payload                      frame as sent
    [InlineData("01 07 01", "", "<01070107>")] //                              IDENTIFY; BCC = '0'^'1'^'0'^'7'^'0'^'1' = 16#07
    [InlineData("01 08 02", "02 04006404 01000002", "<01080202040064040100000208>")] // READ VB100 x4 and IB0 x2
    [InlineData("01 08 82", "00 00000457A503", "<0108820000000457A50372>")] //  its reply: STATUS 00, 6 data bytes
    [InlineData("02 09 03", "04006E012A", "<02090304006E012A0D>")] //          WRITE VB110 := 16#2A at station 2
    [InlineData("01 0A 84", "00 21", "<010A8400217F>")] //                     WRITE BIT reply: byte read back 16#21
    public void Encode_KnownFrame_GivesTheAnnotatedCharacters(string head, string payload, string expected)
    {
        var h = Convert.FromHexString(head.Replace(" ", string.Empty, StringComparison.Ordinal));
        var frame = new FreeportFrame(h[0], h[1], h[2], [.. Convert.FromHexString(payload.Replace(" ", string.Empty, StringComparison.Ordinal))]);

        Encoding.ASCII.GetString(FrameCodec.Encode(frame)).Should().Be(expected);
        FrameCodec.TryDecode(Encoding.ASCII.GetBytes(expected), out var decoded, out var error).Should().BeTrue();
        error.Should().Be(FrameError.None);
        decoded.Should().Be(frame);
    }

    [Theory]
    [InlineData("", FrameError.BadStart)]
    [InlineData("01070107>", FrameError.BadStart)]
    [InlineData("<01070107", FrameError.BadEnd)]
    [InlineData("<", FrameError.BadEnd)]
    [InlineData("<010701>", FrameError.TooShort)] //          6 body characters, 8 needed
    [InlineData("<><", FrameError.BadEnd)]
    [InlineData("<0107010>", FrameError.TooShort)] //         7 body characters: shortness is checked before oddness
    [InlineData("<010701070>", FrameError.OddLength)] //      9 body characters
    [InlineData("<01070a07>", FrameError.NotHex)] //          lowercase is not what ATH accepts
    [InlineData("<0107G107>", FrameError.NotHex)]
    [InlineData("<01<70107>", FrameError.NotHex)]
    [InlineData("<01070108>", FrameError.ChecksumMismatch)] // 16#07 expected
    [InlineData("<01070207>", FrameError.ChecksumMismatch)] // one body bit flipped
    public void TryDecode_MalformedFrame_ReportsTheError(string text, FrameError expected)
    {
        FrameCodec.TryDecode(Encoding.ASCII.GetBytes(text), out _, out var error).Should().BeFalse();
        error.Should().Be(expected);
    }

    [Fact]
    public void TryDecode_MoreThan255Characters_ReportsTooLong()
    {
        var text = "<" + new string('0', 254) + ">";

        FrameCodec.TryDecode(Encoding.ASCII.GetBytes(text), out _, out var error).Should().BeFalse();
        error.Should().Be(FrameError.TooLong);
    }

    [Fact]
    public void Encode_LongestPayload_Gives255Characters()
    {
        var frame = new FreeportFrame(1, 0, 0x82, [.. new byte[ProtocolLimits.MaxBodyBytes - FreeportFrame.OverheadBytes]]);

        FrameCodec.Encode(frame).Should().HaveCount(254);
        FrameCodec.TryDecode(FrameCodec.Encode(frame), out var decoded, out _).Should().BeTrue();
        decoded.Should().Be(frame);
    }

    [Fact]
    public void Encode_PayloadPastTheBuffer_Throws()
    {
        var frame = new FreeportFrame(1, 0, 0x82, [.. new byte[ProtocolLimits.MaxBodyBytes - FreeportFrame.OverheadBytes + 1]]);

        var act = () => FrameCodec.Encode(frame);

        act.Should().Throw<ArgumentException>();
    }

    [Fact]
    public void BlockCheck_Characters_IsTheirXor()
    {
        BlockCheck.Compute("010701"u8).Should().Be(0x07);
        BlockCheck.Compute(ReadOnlySpan<byte>.Empty).Should().Be(0x00);
        ImmutableArray.Create<byte>(0x30, 0x41).Aggregate(0, (a, b) => a ^ b).Should().Be(BlockCheck.Compute("0A"u8));
    }
}
