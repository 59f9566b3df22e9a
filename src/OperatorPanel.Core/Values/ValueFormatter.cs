using System.Buffers.Binary;
using System.Globalization;
using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Values;

/// <summary>
/// Shows the bytes of an address as the operator reads them. Bytes are big-endian as the S7-200 stores them
/// (VW100 = VB100 high, VB101 low); a bit address holds one byte, 00 or 01, as <see cref="Polling.PolledValue.Raw"/> does.
/// Numbers use STL notation: 16#0A3F, 2#0000_1010; a REAL is IEEE 754 single precision from a double word.
/// </summary>
public static class ValueFormatter
{
    /// <summary>
    /// The text of <paramref name="raw"/> in <paramref name="format"/>. Throws when the bytes do not match the width or the
    /// format does not fit it (<see cref="DisplayFormats.Fits"/>): those are the caller's mistakes, not the operator's.
    /// </summary>
    public static string Format(ReadOnlySpan<byte> raw, AccessWidth width, DisplayFormat format)
    {
        if (raw.Length != width.ByteCount())
        {
            throw new ArgumentException($"a {width} value has {width.ByteCount()} bytes, not {raw.Length}", nameof(raw));
        }

        if (!format.Fits(width))
        {
            throw new ArgumentException($"{format} does not fit a {width} value", nameof(format));
        }

        return format switch
        {
            DisplayFormat.Bool => raw[0] != 0 ? "1" : "0",
            DisplayFormat.Unsigned => Unsigned(raw).ToString(CultureInfo.InvariantCulture),
            DisplayFormat.Signed => Signed(raw).ToString(CultureInfo.InvariantCulture),
            DisplayFormat.Hex => Hex(raw),
            DisplayFormat.Binary => Binary(raw),
            DisplayFormat.Float => BitConverter.UInt32BitsToSingle(BinaryPrimitives.ReadUInt32BigEndian(raw)).ToString(CultureInfo.InvariantCulture),
            DisplayFormat.Ascii => Ascii(raw),
        };
    }

    /// <summary>16#00FF: two digits per byte.</summary>
    public static string Hex(ReadOnlySpan<byte> raw) => "16#" + Convert.ToHexString(raw);

    /// <summary>2#0000_1010: eight digits per byte, in groups of four.</summary>
    public static string Binary(ReadOnlySpan<byte> raw)
    {
        var text = new StringBuilder("2#");
        for (var i = 0; i < raw.Length; i++)
        {
            var bits = Convert.ToString(raw[i], 2).PadLeft(8, '0');
            text.Append(i == 0 ? string.Empty : "_").Append(bits[..4]).Append('_').Append(bits[4..]);
        }

        return text.ToString();
    }

    public static ulong Unsigned(ReadOnlySpan<byte> raw)
    {
        ulong value = 0;
        foreach (var b in raw)
        {
            value = (value << 8) | b;
        }

        return value;
    }

    /// <summary>Two's complement over the value's own width (INT for a word, DINT for a double word).</summary>
    public static long Signed(ReadOnlySpan<byte> raw)
    {
        var bits = 8 * raw.Length;
        var value = (long)Unsigned(raw);
        return (value & (1L << (bits - 1))) != 0 ? value - (1L << bits) : value;
    }

    /// <summary>Printable ASCII as is; any other byte shows as '.' so the text keeps one character per byte.</summary>
    private static string Ascii(ReadOnlySpan<byte> raw)
    {
        var chars = new char[raw.Length];
        for (var i = 0; i < raw.Length; i++)
        {
            chars[i] = raw[i] is >= 0x20 and <= 0x7E ? (char)raw[i] : '.';
        }

        return new string(chars);
    }
}
