using System.Collections.Immutable;
using System.Text;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

public sealed class FrameCodecTests
{
    [Theory]
    //           ST SQ CM payload                          frame as sent: body, then CRC-16/MCRF4XX low nibble first as 16#60 + nibble
    [InlineData("01 07 01", "", "<010701dl`l>")] //                                  IDENTIFY; CRC 16#C0C4: 4 'd', C 'l', 0 '`', C 'l'
    [InlineData("01 08 02", "02 04006404 01000002", "<010802020400640401000002mmdj>")] // READ VD100 and IB0 x2; CRC 16#A4DD
    [InlineData("01 08 82", "00 A4DD 00000457A503", "<01088200A4DD00000457A503jnic>")] // its reply: STATUS 00, REQCHECK A4DD, 6 data bytes
    [InlineData("02 09 03", "04006E012A", "<02090304006E012Aaenb>")] //              WRITE VB110 := 16#2A at station 2; CRC 16#2E51
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
    [InlineData("010701dl`l>", FrameError.BadStart)]
    [InlineData("<010701dl`l", FrameError.BadEnd)]
    [InlineData("<", FrameError.BadEnd)]
    [InlineData("<0107dl`l>", FrameError.TooShort)] //          4 body characters, 6 needed
    [InlineData("<><", FrameError.BadEnd)]
    [InlineData("<01070dl`l>", FrameError.TooShort)] //         5 body characters: shortness is checked before oddness
    [InlineData("<0107010dl`l>", FrameError.OddLength)] //      7 body characters (a lost body character)
    [InlineData("<01070adl`l>", FrameError.NotHex)] //          lowercase is not what ATH accepts
    [InlineData("<0107G1dl`l>", FrameError.NotHex)]
    [InlineData("<01<701dl`l>", FrameError.NotHex)]
    [InlineData("<010701dl`l`l>", FrameError.NotHex)] //       check characters where body digits belong: the body ends 4 before the end
    [InlineData("<010701DL`L>", FrameError.BadCheckCharacter)] // hex digits where the check belongs (a v1 BCC looks like this)
    [InlineData("<0107010107>", FrameError.BadCheckCharacter)] // the v1 IDENTIFY probe
    [InlineData("<010701dl`m>", FrameError.ChecksumMismatch)] // one check bit flipped
    [InlineData("<010700dl`l>", FrameError.ChecksumMismatch)] // one body bit flipped
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
    public void FrameCheck_CatalogueInput_GivesTheCatalogueCheckValue()
    {
        FrameCheck.Compute("123456789"u8).Should().Be(0x6F91);
        FrameCheck.Compute(ReadOnlySpan<byte>.Empty).Should().Be(FrameCheck.Initial);
    }
}
