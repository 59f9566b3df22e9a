using System.Text;

namespace OperatorPanel.Stl.Tests;

public sealed class AwlSourceTests
{
    static AwlSourceTests() => Encoding.RegisterProvider(CodePagesEncodingProvider.Instance);

    [Fact]
    public void Decode_Utf8WithMark_MarkDroppedFromTheText()
    {
        var source = AwlSource.Decode([0xEF, 0xBB, 0xBF, .. Encoding.UTF8.GetBytes("LD     Zähler")]);

        (source.Kind, source.HasByteOrderMark, source.Text).Should().Be((AwlTextEncoding.Utf8WithByteOrderMark, true, "LD     Zähler"));
    }

    [Fact]
    public void Decode_Utf8WithoutMark_Utf8()
    {
        var source = AwlSource.Decode(Encoding.UTF8.GetBytes("CALL   计数"));

        (source.Kind, source.Text).Should().Be((AwlTextEncoding.Utf8, "CALL   计数"));
    }

    [Fact]
    public void Decode_GermanExport_CodePage1252()
    {
        const string text = "SUBROUTINE_BLOCK Zähler:SBR0\r\nTITLE=Füllstand, Größe\r\n";
        var source = AwlSource.Decode(Encoding.GetEncoding(1252).GetBytes(text));

        (source.Kind, source.Text, source.EncodingName).Should().Be((AwlTextEncoding.Windows1252, text, "Windows-1252"));
    }

    [Fact]
    public void Decode_ChineseExport_Gbk()
    {
        const string text = "SUBROUTINE_BLOCK 系统初始化:SBR0\r\nTITLE=上电初始化 —— 工艺参数\r\n";
        var source = AwlSource.Decode(Encoding.GetEncoding(936).GetBytes(text));

        (source.Kind, source.Text, source.EncodingName).Should().Be((AwlTextEncoding.Gbk, text, "GBK (936)"));
    }

    [Fact]
    public void Decode_AsciiOnly_Ascii()
    {
        AwlSource.Decode(Encoding.ASCII.GetBytes("LD     I0.0\r\n")).Kind.Should().Be(AwlTextEncoding.Ascii);
    }

    [Fact]
    public void ByteText_WrittenBackAsLatin1_IsTheFilesBytes()
    {
        var bytes = Encoding.GetEncoding(936).GetBytes("CALL   计数 // 光电\r\n");

        Encoding.Latin1.GetBytes(AwlSource.Decode(bytes).ByteText).Should().Equal(bytes);
    }

    [Fact]
    public void FromText_CharactersUpTo255_AreTheirBytes()
    {
        var source = AwlSource.FromText("LD     SM0.0 // F\u00fcllstand");

        source.Bytes[^8].Should().Be(0xFC);
        source.Text.Should().Be("LD     SM0.0 // F\u00fcllstand");
    }
}
