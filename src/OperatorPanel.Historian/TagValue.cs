using System.Buffers.Binary;
using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Historian;

/// <summary>
/// A value's bytes as the historian stores them (one unsigned big-endian integer: a bit is 0/1, a word 0-65535, a
/// double word its 32 bits) and as it trends them (the number the panel shows in the tag's format: a REAL's float, an
/// INT's sign; codes such as hex show their unsigned number).
/// </summary>
public static class TagValue
{
    /// <summary>The stored integer of <paramref name="raw"/> (the address's 1, 2 or 4 bytes, or 00/01 for a bit).</summary>
    public static long ToStored(ImmutableArray<byte> raw) => (long)ValueFormatter.Unsigned(raw.AsSpan());

    /// <summary>The stored integer back into the address's bytes.</summary>
    public static ImmutableArray<byte> ToRaw(long stored, PlcAddress address)
    {
        var count = address.Width == AccessWidth.Bit ? 1 : address.Width.ByteCount();
        var bytes = new byte[count];
        for (var i = count - 1; i >= 0; i--)
        {
            bytes[i] = (byte)(stored & 0xFF);
            stored >>= 8;
        }

        return [.. bytes];
    }

    /// <summary>The number a trend plots for the stored integer of <paramref name="address"/> shown as <paramref name="format"/>.</summary>
    public static double ToNumber(long stored, PlcAddress address, DisplayFormat format)
    {
        var raw = ToRaw(stored, address).AsSpan();
        return format switch
        {
            DisplayFormat.Float when raw.Length == 4 => BitConverter.UInt32BitsToSingle(BinaryPrimitives.ReadUInt32BigEndian(raw)),
            DisplayFormat.Signed => ValueFormatter.Signed(raw),
            _ => ValueFormatter.Unsigned(raw),
        };
    }

    /// <summary>The text the panel shows for the stored integer (16#002A, 2#..., 'AB', 1.5).</summary>
    public static string ToText(long stored, PlcAddress address, DisplayFormat format)
    {
        var width = address.Width;
        return format.Fits(width) ? ValueFormatter.Format(ToRaw(stored, address).AsSpan(), width, format) : stored.ToString(System.Globalization.CultureInfo.InvariantCulture);
    }
}
