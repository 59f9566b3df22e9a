using System.Text;

namespace OperatorPanel.Stl;

/// <summary>
/// An .awl file as read: its bytes, the text they decode to (without a byte order mark) and the encoding found. Micro/WIN
/// exports in the Windows code page of the PC it runs on (1252 in Western Europe, GBK/936 in China; docs/awl-exports.md,
/// "Encoding"); a file edited elsewhere may be UTF-8, with or without a byte order mark. The text is what diagnostics and
/// names use; the bytes are what a merge writes back, unchanged.
/// </summary>
public sealed class AwlSource
{
    private static readonly byte[] Utf8Mark = [0xEF, 0xBB, 0xBF];

    static AwlSource() => Encoding.RegisterProvider(CodePagesEncodingProvider.Instance);

    private AwlSource(byte[] bytes, string text, Encoding encoding, AwlTextEncoding kind)
    {
        Bytes = bytes;
        Text = text;
        Encoding = encoding;
        Kind = kind;
    }

    public byte[] Bytes { get; }

    /// <summary>The decoded text, without the byte order mark.</summary>
    public string Text { get; }

    public Encoding Encoding { get; }

    public AwlTextEncoding Kind { get; }

    public bool HasByteOrderMark => Kind == AwlTextEncoding.Utf8WithByteOrderMark;

    /// <summary>The bytes one character per byte (Latin-1): lines of this string written back as Latin-1 are the file's bytes.</summary>
    public string ByteText => Encoding.Latin1.GetString(Bytes);

    /// <summary>"UTF-8 with BOM", "UTF-8", "ASCII", "Windows-1252", "GBK (936)".</summary>
    public string EncodingName => Kind switch
    {
        AwlTextEncoding.Utf8WithByteOrderMark => "UTF-8 with BOM",
        AwlTextEncoding.Utf8 => "UTF-8",
        AwlTextEncoding.Ascii => "ASCII",
        AwlTextEncoding.Windows1252 => "Windows-1252",
        AwlTextEncoding.Gbk => "GBK (936)",
    };

    /// <summary>
    /// UTF-8 when the bytes start with its mark or are valid UTF-8 with characters above 127; otherwise GBK when every
    /// byte above 127 pairs into a GBK character and most pairs are two such bytes (Chinese text); otherwise 1252, where
    /// an umlaut is one byte among ASCII letters.
    /// </summary>
    public static AwlSource Decode(byte[] bytes)
    {
        ArgumentNullException.ThrowIfNull(bytes);
        if (bytes.AsSpan().StartsWith(Utf8Mark))
        {
            return new AwlSource(bytes, Encoding.UTF8.GetString(bytes, Utf8Mark.Length, bytes.Length - Utf8Mark.Length), Encoding.UTF8, AwlTextEncoding.Utf8WithByteOrderMark);
        }

        if (bytes.All(b => b < 0x80))
        {
            return new AwlSource(bytes, Encoding.ASCII.GetString(bytes), Encoding.ASCII, AwlTextEncoding.Ascii);
        }

        if (TryStrict(new UTF8Encoding(false, throwOnInvalidBytes: true), bytes, out var utf8))
        {
            return new AwlSource(bytes, utf8, Encoding.UTF8, AwlTextEncoding.Utf8);
        }

        if (LooksLikeGbk(bytes))
        {
            var gbk = Encoding.GetEncoding(936);
            return new AwlSource(bytes, gbk.GetString(bytes), gbk, AwlTextEncoding.Gbk);
        }

        var windows = Encoding.GetEncoding(1252);
        return new AwlSource(bytes, windows.GetString(bytes), windows, AwlTextEncoding.Windows1252);
    }

    /// <summary>
    /// A text that was not read from a file (tests, a program typed in): characters up to 255 are its bytes one by one,
    /// as an export in 1252 would hold them; a text with wider characters is taken as UTF-8.
    /// </summary>
    public static AwlSource FromText(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        return Decode(text.All(c => c <= '\u00FF') ? Encoding.Latin1.GetBytes(text) : Encoding.UTF8.GetBytes(text));
    }

    private static bool TryStrict(Encoding encoding, byte[] bytes, out string text)
    {
        try
        {
            text = encoding.GetString(bytes);
            return true;
        }
        catch (DecoderFallbackException)
        {
            text = string.Empty;
            return false;
        }
    }

    /// <summary>
    /// GBK: a lead byte 0x81-0xFE and a trail byte 0x40-0xFE except 0x7F. Chinese text keeps both bytes above 127 in
    /// almost every character (all of GB2312); a 1252 text's umlaut followed by an ASCII letter fits GBK's rules too, so
    /// pairs with an ASCII trail byte may be a quarter of the pairs at most.
    /// </summary>
    private static bool LooksLikeGbk(byte[] bytes)
    {
        var (high, low) = (0, 0);
        for (var i = 0; i < bytes.Length; i++)
        {
            var lead = bytes[i];
            if (lead < 0x80)
            {
                continue;
            }

            if (lead == 0x80 || lead == 0xFF || i + 1 >= bytes.Length || bytes[i + 1] is < 0x40 or 0x7F or 0xFF)
            {
                return false;
            }

            if (bytes[++i] >= 0x80)
            {
                high++;
            }
            else
            {
                low++;
            }
        }

        return high > 0 && low * 4 <= high;
    }
}
