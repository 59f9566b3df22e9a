using System.Globalization;
using System.Text;

namespace OperatorPanel.TestKit;

/// <summary>Bytes written as hex in tests: Parse("3C 30 31") and Format(bytes) == "3C 30 31".</summary>
public static class Hex
{
    /// <summary>Pairs of hex digits; spaces, line breaks and "// comments" to the end of a line are ignored.</summary>
    public static byte[] Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var digits = new StringBuilder();
        foreach (var line in text.Split('\n'))
        {
            var code = line.Split("//", 2)[0];
            digits.Append(code.Where(c => !char.IsWhiteSpace(c)).ToArray());
        }

        if (digits.Length % 2 != 0)
        {
            throw new FormatException($"odd number of hex digits in \"{text}\"");
        }

        var bytes = new byte[digits.Length / 2];
        for (var i = 0; i < bytes.Length; i++)
        {
            var pair = digits.ToString(i * 2, 2);
            if (!byte.TryParse(pair, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out bytes[i]))
            {
                throw new FormatException($"\"{pair}\" is not a hex byte in \"{text}\"");
            }
        }

        return bytes;
    }

    public static string Format(ReadOnlySpan<byte> bytes) =>
        string.Join(' ', bytes.ToArray().Select(b => b.ToString("X2", CultureInfo.InvariantCulture)));

    /// <summary>The ASCII bytes of a frame written as text, e.g. Ascii("&lt;0101017E&gt;").</summary>
    public static byte[] Ascii(string text) => Encoding.ASCII.GetBytes(text);
}
