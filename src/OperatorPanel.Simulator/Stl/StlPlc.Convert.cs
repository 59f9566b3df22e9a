using System.Globalization;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Conversions (A5E00307987-04 chapter 6, "Conversion Instructions"): DTR, ROUND (to the nearest, a half away from
/// zero) and TRUNC (toward zero) with SM1.1 and an unchanged OUT when the real does not fit a double integer; BCDI/IBCD
/// in place with SM1.6 on an invalid BCD digit or a value outside 0-9999; DECO/ENCO; SEG (the manual's segment table:
/// bit 0 = segment a ... bit 6 = g); ITA (8 characters), DTA (12) and RTA (FMT's size) right-justified ASCII.
/// </summary>
public sealed partial class StlPlc
{
    private const byte InvalidBcd = 0x40;

    /// <summary>SEG: the segments lit for the hex digits 0-F (A5E00307987-04, "Segment" instruction's table).</summary>
    private static readonly byte[] Segments =
        [0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07, 0x7F, 0x67, 0x77, 0x7C, 0x39, 0x5E, 0x79, 0x71];

    private void Convert(StlOp op)
    {
        switch (op.Code)
        {
            case StlOpCode.Dtr: Write(op.B!, 4, BitConverter.SingleToUInt32Bits((int)Read(op.A!, 4))); break;
            case StlOpCode.Round: RealToInteger(op, MathF.Round(ReadReal(op.A!), MidpointRounding.AwayFromZero)); break;
            case StlOpCode.Trunc: RealToInteger(op, MathF.Truncate(ReadReal(op.A!))); break;
            case StlOpCode.Bcdi: BcdToInteger(op.A!); break;
            case StlOpCode.Ibcd: IntegerToBcd(op.A!); break;
            case StlOpCode.Deco: Write(op.B!, 2, 1u << (int)(Read(op.A!, 1) & 0x0F)); break;
            case StlOpCode.Enco: Encode(op); break;
            case StlOpCode.Seg: Write(op.B!, 1, Segments[Read(op.A!, 1) & 0x0F]); break;
            case StlOpCode.Ita: ToAscii(op, ((short)Read(op.A!, 2)).ToString(CultureInfo.InvariantCulture), 8, 5); break;
            case StlOpCode.Dta: ToAscii(op, ((int)Read(op.A!, 4)).ToString(CultureInfo.InvariantCulture), 12, 7); break;
            case StlOpCode.Rta: RealToAscii(op); break;
            default: Rotate(op); break;
        }
    }

    private void RealToInteger(StlOp op, float value)
    {
        if (!float.IsFinite(value) || value < int.MinValue || value >= 2147483648f)
        {
            SetFlags(Overflow, Overflow);
            _eno = false;
            return;
        }

        Write(op.B!, 4, (uint)(int)value);
        SetFlags(Overflow, 0);
    }

    private void BcdToInteger(StlLoc loc)
    {
        var bcd = Read(loc, 2);
        var value = 0u;
        for (var shift = 12; shift >= 0; shift -= 4)
        {
            var digit = (bcd >> shift) & 0xF;
            if (digit > 9)
            {
                SetFlags(InvalidBcd, InvalidBcd);
                _eno = false;
                return;
            }

            value = (value * 10) + digit;
        }

        Write(loc, 2, value);
        SetFlags(InvalidBcd, 0);
    }

    private void IntegerToBcd(StlLoc loc)
    {
        var value = (short)Read(loc, 2);
        if (value is < 0 or > 9999)
        {
            SetFlags(InvalidBcd, InvalidBcd);
            _eno = false;
            return;
        }

        var bcd = 0u;
        for (var shift = 0; shift < 16; shift += 4, value /= 10)
        {
            bcd |= (uint)(value % 10) << shift;
        }

        Write(loc, 2, bcd);
        SetFlags(InvalidBcd, 0);
    }

    /// <summary>
    /// ENCO: the number of the lowest set bit of IN (C233 p. 9-131 writes it "into the least significant nibble" of OUT;
    /// whether the upper nibble is cleared, as here, or kept is not said); with no bit set OUT is left as it was
    /// (unconfirmed).
    /// </summary>
    private void Encode(StlOp op)
    {
        var value = Read(op.A!, 2);
        if (value != 0)
        {
            Write(op.B!, 1, (uint)System.Numerics.BitOperations.TrailingZeroCount(value));
        }
    }

    /// <summary>
    /// ITA/DTA IN, OUT, FMT: FMT bits 0-2 = digits right of the decimal point, bit 3 = comma (1) or period (0). A digit
    /// count above <paramref name="maxDigits"/> fills the buffer with spaces; otherwise the number is right-justified
    /// with a leading 0 before the point.
    /// </summary>
    private void ToAscii(StlOp op, string digits, int size, int maxDigits)
    {
        var format = (int)Read(op.C!, 1);
        var decimals = format & 0x07;
        var text = decimals > maxDigits ? new string(' ', size) : Place(digits, decimals, (format & 0x08) != 0 ? ',' : '.');
        WriteText(op.B!, text.PadLeft(size), size);
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

    /// <summary>RTA IN, OUT, FMT: FMT bits 4-7 = buffer size (3-15), bits 0-2 digits after the point (0-5), bit 3 comma; a value too wide for the buffer is written as asterisks.</summary>
    private void RealToAscii(StlOp op)
    {
        var format = (int)Read(op.C!, 1);
        var size = format >> 4;
        var decimals = format & 0x07;
        if (size < 3)
        {
            _eno = false;
            return;
        }

        var value = ReadReal(op.A!);
        var text = decimals > 5 || size <= decimals + 1 ? new string(' ', size)
            : Place(Math.Round((double)value * Math.Pow(10, decimals), MidpointRounding.AwayFromZero).ToString("0", CultureInfo.InvariantCulture), decimals, (format & 0x08) != 0 ? ',' : '.');
        WriteText(op.B!, text.Length > size || !float.IsFinite(value) ? new string('*', size) : text.PadLeft(size), size);
    }

    private void WriteText(StlLoc target, string text, int size)
    {
        if (TrySpan(target, size, out var area, out var offset))
        {
            for (var i = 0; i < size; i++)
            {
                area[offset + i] = (byte)text[i];
            }
        }
    }
}
