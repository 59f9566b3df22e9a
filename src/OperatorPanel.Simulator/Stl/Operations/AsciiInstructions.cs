using System.Globalization;
using OperatorPanel.Simulator.Stl.Execution;
using static OperatorPanel.Simulator.Stl.Operations.StatusBits;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// ASCII conversions. ITA (8 characters), DTA (12) and RTA (FMT's size) write right-justified ASCII (A5E00307987-04
/// chapter 6, "Conversion Instructions"). ATH and HTA (docs/sources/s7200-facts.md section 9): LEN counts ASCII
/// characters / hex digits, and each takes <see cref="StlTiming.PerByte"/> per character on top of its base time.
/// </summary>
internal static class AsciiInstructions
{
    public static void IntegerToAscii(StlMachine m, StlOp op) =>
        ToAscii(m, op, ((short)m.Read(op.A!, 2)).ToString(CultureInfo.InvariantCulture), 8, 5);

    public static void DoubleToAscii(StlMachine m, StlOp op) =>
        ToAscii(m, op, ((int)m.Read(op.A!, 4)).ToString(CultureInfo.InvariantCulture), 12, 7);

    /// <summary>RTA IN, OUT, FMT: FMT bits 4-7 = buffer size (3-15), bits 0-2 digits after the point (0-5), bit 3 comma; a value too wide for the buffer is written as asterisks.</summary>
    public static void RealToAscii(StlMachine m, StlOp op)
    {
        var format = (int)m.Read(op.C!, 1);
        var size = format >> 4;
        var decimals = format & 0x07;
        if (size < 3)
        {
            m.Eno = false;
            return;
        }

        var value = m.ReadReal(op.A!);
        var text = decimals > 5 || size <= decimals + 1 ? new string(' ', size)
            : Place(Math.Round((double)value * Math.Pow(10, decimals), MidpointRounding.AwayFromZero).ToString("0", CultureInfo.InvariantCulture), decimals, (format & 0x08) != 0 ? ',' : '.');
        WriteText(m, op.B!, text.Length > size || !float.IsFinite(value) ? new string('*', size) : text.PadLeft(size), size);
    }

    /// <summary>
    /// ATH: legal characters are 16#30-39 and 16#41-46 only; an illegal one sets SM1.7 and leaves its nibble unchanged.
    /// An odd LEN leaves the low nibble of the last output byte unchanged.
    /// </summary>
    public static void AsciiToHex(StlMachine m, StlOp op)
    {
        var length = (int)m.Read(op.C!, 1);
        if (!m.TrySpan(op.A!, length, out var input, out var at) || !m.TrySpan(op.B!, (length + 1) / 2, out var output, out var to))
        {
            return;
        }

        var illegal = false;
        for (var i = 0; i < length; i++)
        {
            var c = input[at + i];
            int nibble = c switch
            {
                >= 0x30 and <= 0x39 => c - 0x30,
                >= 0x41 and <= 0x46 => c - 0x41 + 10,
                _ => -1,
            };
            if (nibble < 0)
            {
                illegal = true;
                continue;
            }

            ref var target = ref output[to + (i / 2)];
            target = i % 2 == 0 ? (byte)((target & 0x0F) | (nibble << 4)) : (byte)((target & 0xF0) | nibble);
        }

        m.SetFlags(IllegalAscii, illegal ? IllegalAscii : (byte)0);
        m.Charge(length * StlTiming.PerByte);
    }

    public static void HexToAscii(StlMachine m, StlOp op)
    {
        var length = (int)m.Read(op.C!, 1);
        if (!m.TrySpan(op.A!, (length + 1) / 2, out var input, out var at) || !m.TrySpan(op.B!, length, out var output, out var to))
        {
            return;
        }

        for (var i = 0; i < length; i++)
        {
            var source = input[at + (i / 2)];
            var nibble = i % 2 == 0 ? source >> 4 : source & 0x0F;
            output[to + i] = (byte)(nibble < 10 ? 0x30 + nibble : 0x41 + nibble - 10);
        }

        m.Charge(length * StlTiming.PerByte);
    }

    /// <summary>
    /// ITA/DTA IN, OUT, FMT: FMT bits 0-2 = digits right of the decimal point, bit 3 = comma (1) or period (0). A digit
    /// count above <paramref name="maxDigits"/> fills the buffer with spaces; otherwise the number is right-justified
    /// with a leading 0 before the point.
    /// </summary>
    private static void ToAscii(StlMachine m, StlOp op, string digits, int size, int maxDigits)
    {
        var format = (int)m.Read(op.C!, 1);
        var decimals = format & 0x07;
        var text = decimals > maxDigits ? new string(' ', size) : Place(digits, decimals, (format & 0x08) != 0 ? ',' : '.');
        WriteText(m, op.B!, text.PadLeft(size), size);
    }

    private static string Place(string digits, int decimals, char point)
    {
        if (decimals == 0)
        {
            return digits;
        }

        var negative = digits.StartsWith('-');
        var magnitude = (negative ? digits[1..] : digits).PadLeft(decimals + 1, '0');
        return (negative ? "-" : string.Empty) + magnitude[..^decimals] + point + magnitude[^decimals..];
    }

    private static void WriteText(StlMachine m, StlLoc target, string text, int size)
    {
        if (m.TrySpan(target, size, out var area, out var offset))
        {
            for (var i = 0; i < size; i++)
            {
                area[offset + i] = (byte)text[i];
            }
        }
    }
}
