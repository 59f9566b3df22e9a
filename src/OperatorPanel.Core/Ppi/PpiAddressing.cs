using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Core.Ppi;

/// <summary>
/// The panel's addresses as S7 items (docs/ppi.md section 6): I, Q, M, SM and S by their area codes, V as data block 1,
/// AIW and AQW as words; bits, bytes, words and double words of the byte areas as bytes (a bit is written as a bit
/// item, so the other seven bits of its byte are left alone); T37 and C5 as timer and counter items, whose answer is 5
/// bytes per element (a status byte, then the value as 4 bytes, most significant first), of which the panel takes the
/// last two: the current value, a signed word as the CPU holds it. L, AC and HC are not reachable over PPI.
/// </summary>
public static class PpiAddressing
{
    public static bool TryArea(MemoryArea area, out S7Area code)
    {
        code = area switch
        {
            MemoryArea.I => S7Area.I,
            MemoryArea.Q => S7Area.Q,
            MemoryArea.M => S7Area.M,
            MemoryArea.V => S7Area.V,
            MemoryArea.SM => S7Area.SM,
            MemoryArea.S => S7Area.S,
            MemoryArea.AI => S7Area.AI,
            MemoryArea.AQ => S7Area.AQ,
            MemoryArea.T => S7Area.T,
            MemoryArea.C => S7Area.C,
            _ => 0,
        };
        return code != 0;
    }

    /// <summary>Where a timer's or counter's current value is in its 5 answer bytes: the low word of the 4-byte value.</summary>
    public const int CurrentValueOffset = S7Item.TimerCounterBytes - 2;

    /// <summary>
    /// The item reading bytes <paramref name="first"/>..+<paramref name="count"/> of <paramref name="area"/> (words for
    /// AI and AQ); for T and C, <paramref name="count"/> elements from number <paramref name="first"/>.
    /// </summary>
    public static bool TryRange(MemoryArea area, int first, int count, out S7Item item, [NotNullWhen(false)] out string? error)
    {
        item = default;
        if (!TryArea(area, out var code))
        {
            error = $"{area} memory cannot be reached over PPI";
            return false;
        }

        if (AreaSyntax.IsNumbered(area))
        {
            item = area == MemoryArea.T ? S7Item.Timers(first, count) : S7Item.Counters(first, count);
            error = null;
            return true;
        }

        if (AreaSyntax.IsAnalog(area) && (first % 2 != 0 || count % 2 != 0))
        {
            error = $"{area} is read in whole words: byte {first}, {count} bytes is not";
            return false;
        }

        item = AreaSyntax.IsAnalog(area) ? S7Item.Words(code, first, count / 2) : S7Item.Bytes(code, first, count);
        error = null;
        return true;
    }

    /// <summary>The item that reads <paramref name="address"/>: its bytes (a bit's byte), or its one timer or counter.</summary>
    public static bool TryRead(PlcAddress address, out S7Item item, [NotNullWhen(false)] out string? error) =>
        TryRange(address.Area, address.ByteOffset, AreaSyntax.IsNumbered(address.Area) ? 1 : address.Width.ByteCount(), out item, out error);

    /// <summary>
    /// The item that writes <paramref name="value"/> to <paramref name="address"/>: a bit item for a bit (0 or 1),
    /// else the address's bytes, most significant first as the S7-200 stores them.
    /// </summary>
    public static bool TryWrite(PlcAddress address, uint value, [NotNullWhen(true)] out S7WriteItem? item, [NotNullWhen(false)] out string? error)
    {
        item = null;
        if (AreaSyntax.IsNumbered(address.Area))
        {
            // No source shows a timer or counter write to an S7-200 (docs/ppi.md section 12): refused, never guessed.
            error = $"{address}: timer and counter current values are not written over PPI";
            return false;
        }

        if (address.Width == AccessWidth.Bit)
        {
            if (!TryArea(address.Area, out var code))
            {
                error = $"{address.Area} memory cannot be reached over PPI";
                return false;
            }

            item = S7WriteItem.Of(S7Item.Bit(code, address.ByteOffset, address.Bit!.Value), [(byte)(value != 0 ? 1 : 0)]);
            error = null;
            return true;
        }

        if (!TryRead(address, out var range, out error))
        {
            return false;
        }

        var count = address.Width.ByteCount();
        var bytes = new byte[count];
        for (var i = 0; i < count; i++)
        {
            bytes[i] = (byte)(value >> (8 * (count - 1 - i)));
        }

        item = S7WriteItem.Of(range, bytes);
        return true;
    }
}
