namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Rotates and the shift register (A5E00307987-04 chapter 6, "Shift and Rotate Instructions"). RLB/RRB/RLW/RRW/RLD/RRD
/// OUT, N rotate by N modulo the width; SM1.1 is the last bit rotated, SM1.0 is set when the value is zero; a count that
/// is 0 after the modulo rotates nothing and leaves SM1.1 alone. SHRB DATA, S_BIT, N shifts DATA into a register of |N|
/// bits from S_BIT (ML801761 printed p. 182, Figure 6-35): N &gt; 0 into S_BIT and out of the most significant bit, N &lt; 0 into the
/// most significant bit and out of S_BIT; the bit shifted out goes to SM1.1. |N| is 1 to 64; any other N sets ENO = 0
/// (error 0092, count field) and shifts nothing.
/// </summary>
public sealed partial class StlPlc
{
    private void Rotate(StlOp op)
    {
        switch (op.Code)
        {
            case StlOpCode.Rlb: Rotate(op, 1, left: true); break;
            case StlOpCode.Rrb: Rotate(op, 1, left: false); break;
            case StlOpCode.Rlw: Rotate(op, 2, left: true); break;
            case StlOpCode.Rrw: Rotate(op, 2, left: false); break;
            case StlOpCode.Rld: Rotate(op, 4, left: true); break;
            case StlOpCode.Rrd: Rotate(op, 4, left: false); break;
            case StlOpCode.Shrb: ShiftRegister(op); break;
            default: throw new InvalidOperationException($"{op.Mnemonic} has no execution (the instruction set maps it to {op.Code})");
        }
    }

    private void Rotate(StlOp op, int bytes, bool left)
    {
        var bits = bytes * 8;
        var count = (int)Read(op.B!, 1) % bits;
        var value = (ulong)Read(op.A!, bytes);
        if (count == 0)
        {
            SetFlags(Zero, value == 0 ? Zero : (byte)0);
            return;
        }

        var result = (uint)((left ? (value << count) | (value >> (bits - count)) : (value >> count) | (value << (bits - count))) & Mask(bytes));
        var lastBit = left ? result & 1 : (result >> (bits - 1)) & 1;
        Write(op.A!, bytes, result);
        SetFlags(Zero | Overflow, (byte)((result == 0 ? Zero : 0) | (lastBit != 0 ? Overflow : 0)));
    }

    private void ShiftRegister(StlOp op)
    {
        var length = (sbyte)Read(op.C!, 1);
        var size = Math.Abs((int)length);
        if (size is 0 or > 64)
        {
            _eno = false;
            return;
        }

        var data = ReadBit(op.A!);
        var first = (op.B!.Offset * 8) + op.B.Bit;
        var limit = (op.B.Kind == StlLocKind.Local ? LBytes : _areas[op.B.Area].Length) * 8;
        if (first + size > limit)
        {
            Failed("OperandRange", $"the {size}-bit shift register from the S_BIT runs past the end of its area");
            return;
        }

        var step = length > 0 ? -1 : 1;
        var (from, to) = length > 0 ? (first + size - 1, first) : (first, first + size - 1);
        var shiftedOut = ReadBit(BitAt(op.B, from));
        for (var n = from; n != to; n += step)
        {
            WriteBit(BitAt(op.B, n), ReadBit(BitAt(op.B, n + step)));
        }

        WriteBit(BitAt(op.B, to), data);
        SetFlags(Overflow, shiftedOut ? Overflow : (byte)0);
    }

    private static StlLoc BitAt(StlLoc start, int bitNumber) =>
        new() { Kind = start.Kind, Area = start.Area, Offset = bitNumber / 8, Bit = bitNumber % 8 };
}
