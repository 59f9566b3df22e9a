using OperatorPanel.Simulator.Stl.Execution;
using static OperatorPanel.Simulator.Stl.Operations.StatusBits;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// Shifts, rotates and the shift register (C233-01 p. 9-116; ML801761 p. 193; A5E00307987-04 chapter 6, "Shift and
/// Rotate Instructions"). SLx/SRx OUT, N: N above the width shifts by the width; SM1.1 is the last bit shifted out.
/// RLx/RRx OUT, N rotate by N modulo the width; SM1.1 is the last bit rotated, SM1.0 is set when the value is zero; a
/// count that is 0 after the modulo rotates nothing and leaves SM1.1 alone. SHRB DATA, S_BIT, N shifts DATA into a
/// register of |N| bits from S_BIT (ML801761 printed p. 182, Figure 6-35): N &gt; 0 into S_BIT and out of the most
/// significant bit, N &lt; 0 into the most significant bit and out of S_BIT; the bit shifted out goes to SM1.1. |N| is
/// 1 to 64; any other N sets ENO = 0 (error 0092, count field) and shifts nothing.
/// </summary>
internal static class ShiftRotateInstructions
{
    public static StlHandler Shift(int bytes, bool left) => (m, op) => ShiftBits(m, op, bytes, left);

    public static StlHandler Rotate(int bytes, bool left) => (m, op) => RotateBits(m, op, bytes, left);

    public static void ShiftRegister(StlMachine m, StlOp op)
    {
        var length = (sbyte)m.Read(op.C!, 1);
        var size = Math.Abs((int)length);
        if (size is 0 or > 64)
        {
            m.Eno = false;
            return;
        }

        var data = m.ReadBit(op.A!);
        var first = (op.B!.Offset * 8) + op.B.Bit;
        if (first + size > m.BitLimit(op.B))
        {
            m.Fail("OperandRange", $"the {size}-bit shift register from the S_BIT runs past the end of its area");
            return;
        }

        var step = length > 0 ? -1 : 1;
        var (from, to) = length > 0 ? (first + size - 1, first) : (first, first + size - 1);
        var shiftedOut = m.ReadBit(BitAt(op.B, from));
        for (var n = from; n != to; n += step)
        {
            m.WriteBit(BitAt(op.B, n), m.ReadBit(BitAt(op.B, n + step)));
        }

        m.WriteBit(BitAt(op.B, to), data);
        m.SetFlags(Overflow, shiftedOut ? Overflow : (byte)0);
    }

    private static void ShiftBits(StlMachine m, StlOp op, int bytes, bool left)
    {
        var bits = bytes * 8;
        var count = Math.Min((int)m.Read(op.B!, 1), bits);
        var value = (ulong)m.Read(op.A!, bytes);
        if (count == 0)
        {
            m.SetFlags(Zero, value == 0 ? Zero : (byte)0);
            return;
        }

        var lastOut = left ? (value >> (bits - count)) & 1 : (value >> (count - 1)) & 1;
        var result = (uint)((left ? value << count : value >> count) & StlMachine.Mask(bytes));
        m.Write(op.A!, bytes, result);
        m.SetFlags(Zero | Overflow, (byte)((result == 0 ? Zero : 0) | (lastOut != 0 ? Overflow : 0)));
    }

    private static void RotateBits(StlMachine m, StlOp op, int bytes, bool left)
    {
        var bits = bytes * 8;
        var count = (int)m.Read(op.B!, 1) % bits;
        var value = (ulong)m.Read(op.A!, bytes);
        if (count == 0)
        {
            m.SetFlags(Zero, value == 0 ? Zero : (byte)0);
            return;
        }

        var result = (uint)((left ? (value << count) | (value >> (bits - count)) : (value >> count) | (value << (bits - count))) & StlMachine.Mask(bytes));
        var lastBit = left ? result & 1 : (result >> (bits - 1)) & 1;
        m.Write(op.A!, bytes, result);
        m.SetFlags(Zero | Overflow, (byte)((result == 0 ? Zero : 0) | (lastBit != 0 ? Overflow : 0)));
    }

    private static StlLoc BitAt(StlLoc start, int bitNumber) =>
        new() { Kind = start.Kind, Area = start.Area, Offset = bitNumber / 8, Bit = bitNumber % 8 };
}
