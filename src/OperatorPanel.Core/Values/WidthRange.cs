using System.Globalization;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Values;

/// <summary>What a byte, word or double word holds: 0..2^n-1 unsigned, -2^(n-1)..2^(n-1)-1 signed (S7-200 INT/DINT).</summary>
internal readonly record struct WidthRange(AccessWidth Width)
{
    public int Bytes => Width.ByteCount();

    public ulong UnsignedMax => (1UL << (8 * Bytes)) - 1;

    public long SignedMin => -(1L << ((8 * Bytes) - 1));

    public long SignedMax => (1L << ((8 * Bytes) - 1)) - 1;

    public string Name => Width switch
    {
        AccessWidth.Bit => "bit",
        AccessWidth.Byte => "byte",
        AccessWidth.Word => "word",
        AccessWidth.DoubleWord => "double word",
    };

    public string UnsignedText => string.Create(CultureInfo.InvariantCulture, $"0..{UnsignedMax}");

    public string SignedText => string.Create(CultureInfo.InvariantCulture, $"{SignedMin}..{SignedMax}");

    public string HexText => "16#" + new string('0', 2 * Bytes) + "..16#" + new string('F', 2 * Bytes);

    public string BinaryText => ValueFormatter.Binary(new byte[Bytes]) + ".." + ValueFormatter.Binary(Enumerable.Repeat((byte)0xFF, Bytes).ToArray());

    /// <summary>The low <see cref="Bytes"/> bytes of <paramref name="value"/>, most significant first (S7-200 byte order).</summary>
    public byte[] BigEndian(ulong value)
    {
        var bytes = new byte[Bytes];
        for (var i = Bytes - 1; i >= 0; i--)
        {
            bytes[i] = (byte)value;
            value >>= 8;
        }

        return bytes;
    }
}
