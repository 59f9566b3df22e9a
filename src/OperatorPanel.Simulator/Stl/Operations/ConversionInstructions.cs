using OperatorPanel.Simulator.Stl.Execution;
using static OperatorPanel.Simulator.Stl.Operations.StatusBits;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// Conversions (A5E00307987-04 chapter 6, "Conversion Instructions"): BTI, ITB and DTI (a value that does not fit sets
/// SM1.1 and leaves OUT unchanged), ITD, DTR, ROUND (to the nearest, a half away from zero) and TRUNC (toward zero)
/// with SM1.1 and an unchanged OUT when the real does not fit a double integer; BCDI/IBCD in place with SM1.6 on an
/// invalid BCD digit or a value outside 0-9999; DECO/ENCO; SEG (the manual's segment table: bit 0 = segment a ... bit
/// 6 = g). The ASCII conversions are in <see cref="AsciiInstructions"/>.
/// </summary>
internal static class ConversionInstructions
{
    /// <summary>SEG: the segments lit for the hex digits 0-F (A5E00307987-04, "Segment" instruction's table).</summary>
    private static readonly byte[] Segments =
        [0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07, 0x7F, 0x67, 0x77, 0x7C, 0x39, 0x5E, 0x79, 0x71];

    public static void ByteToInteger(StlMachine m, StlOp op) => m.Write(op.B!, 2, m.Read(op.A!, 1));

    public static void IntegerToDouble(StlMachine m, StlOp op) => m.Write(op.B!, 4, (uint)(int)(short)m.Read(op.A!, 2));

    public static void IntegerToByte(StlMachine m, StlOp op) => Narrow(m, op.B!, 1, (short)m.Read(op.A!, 2), 0, 255);

    public static void DoubleToInteger(StlMachine m, StlOp op) => Narrow(m, op.B!, 2, (int)m.Read(op.A!, 4), short.MinValue, short.MaxValue);

    public static void DoubleToReal(StlMachine m, StlOp op) => m.Write(op.B!, 4, BitConverter.SingleToUInt32Bits((int)m.Read(op.A!, 4)));

    public static void Round(StlMachine m, StlOp op) => RealToInteger(m, op, MathF.Round(m.ReadReal(op.A!), MidpointRounding.AwayFromZero));

    public static void Truncate(StlMachine m, StlOp op) => RealToInteger(m, op, MathF.Truncate(m.ReadReal(op.A!)));

    public static void BcdToInteger(StlMachine m, StlOp op)
    {
        var bcd = m.Read(op.A!, 2);
        var value = 0u;
        for (var shift = 12; shift >= 0; shift -= 4)
        {
            var digit = (bcd >> shift) & 0xF;
            if (digit > 9)
            {
                m.SetFlags(InvalidBcd, InvalidBcd);
                m.Eno = false;
                return;
            }

            value = (value * 10) + digit;
        }

        m.Write(op.A!, 2, value);
        m.SetFlags(InvalidBcd, 0);
    }

    public static void IntegerToBcd(StlMachine m, StlOp op)
    {
        var value = (short)m.Read(op.A!, 2);
        if (value is < 0 or > 9999)
        {
            m.SetFlags(InvalidBcd, InvalidBcd);
            m.Eno = false;
            return;
        }

        var bcd = 0u;
        for (var shift = 0; shift < 16; shift += 4, value /= 10)
        {
            bcd |= (uint)(value % 10) << shift;
        }

        m.Write(op.A!, 2, bcd);
        m.SetFlags(InvalidBcd, 0);
    }

    public static void Decode(StlMachine m, StlOp op) => m.Write(op.B!, 2, 1u << (int)(m.Read(op.A!, 1) & 0x0F));

    /// <summary>
    /// ENCO: the number of the lowest set bit of IN (C233 p. 9-131 writes it "into the least significant nibble" of OUT;
    /// whether the upper nibble is cleared, as here, or kept is not said); with no bit set OUT is left as it was
    /// (unconfirmed).
    /// </summary>
    public static void Encode(StlMachine m, StlOp op)
    {
        var value = m.Read(op.A!, 2);
        if (value != 0)
        {
            m.Write(op.B!, 1, (uint)System.Numerics.BitOperations.TrailingZeroCount(value));
        }
    }

    public static void Segment(StlMachine m, StlOp op) => m.Write(op.B!, 1, Segments[m.Read(op.A!, 1) & 0x0F]);

    private static void RealToInteger(StlMachine m, StlOp op, float value)
    {
        if (!float.IsFinite(value) || value < int.MinValue || value >= 2147483648f)
        {
            m.SetFlags(Overflow, Overflow);
            m.Eno = false;
            return;
        }

        m.Write(op.B!, 4, (uint)(int)value);
        m.SetFlags(Overflow, 0);
    }

    /// <summary>ITB/DTI: a value that does not fit sets SM1.1 and the output is not affected.</summary>
    private static void Narrow(StlMachine m, StlLoc target, int bytes, long value, long min, long max)
    {
        if (value < min || value > max)
        {
            m.SetFlags(Overflow, Overflow);
            m.Eno = false;
            return;
        }

        m.Write(target, bytes, (uint)value);
        m.SetFlags(Overflow, 0);
    }
}
