using OperatorPanel.Simulator.Stl.Execution;
using static OperatorPanel.Simulator.Stl.Operations.StatusBits;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// Integer arithmetic in the STL form OUT = OUT op IN (-I and /I subtract and divide IN from OUT) with the SMB1 flags:
/// SM1.0 zero, SM1.1 overflow, SM1.2 negative, SM1.3 division by zero (seed 002, Table C-2). MUL/DIV take the low
/// word of OUT and write 32 bits (C233-01 p. 9-76).
/// </summary>
internal static class IntegerMathInstructions
{
    public static void AddInteger(StlMachine m, StlOp op) => Signed(m, op.B!, 2, (long)(short)m.Read(op.B!, 2) + (short)m.Read(op.A!, 2));

    public static void SubtractInteger(StlMachine m, StlOp op) => Signed(m, op.B!, 2, (long)(short)m.Read(op.B!, 2) - (short)m.Read(op.A!, 2));

    public static void MultiplyInteger(StlMachine m, StlOp op) => Signed(m, op.B!, 2, (long)(short)m.Read(op.B!, 2) * (short)m.Read(op.A!, 2));

    public static void DivideInteger(StlMachine m, StlOp op) => Divide(m, op, 2, (short)m.Read(op.B!, 2), (short)m.Read(op.A!, 2));

    public static void AddDouble(StlMachine m, StlOp op) => Signed(m, op.B!, 4, (long)(int)m.Read(op.B!, 4) + (int)m.Read(op.A!, 4));

    public static void SubtractDouble(StlMachine m, StlOp op) => Signed(m, op.B!, 4, (long)(int)m.Read(op.B!, 4) - (int)m.Read(op.A!, 4));

    public static void MultiplyDouble(StlMachine m, StlOp op) => Signed(m, op.B!, 4, (long)(int)m.Read(op.B!, 4) * (int)m.Read(op.A!, 4));

    public static void DivideDouble(StlMachine m, StlOp op) => Divide(m, op, 4, (int)m.Read(op.B!, 4), (int)m.Read(op.A!, 4));

    public static void IncrementByte(StlMachine m, StlOp op) => Unsigned(m, op.A!, m.Read(op.A!, 1) + 1L);

    public static void DecrementByte(StlMachine m, StlOp op) => Unsigned(m, op.A!, m.Read(op.A!, 1) - 1L);

    public static void IncrementWord(StlMachine m, StlOp op) => Signed(m, op.A!, 2, (short)m.Read(op.A!, 2) + 1L);

    public static void DecrementWord(StlMachine m, StlOp op) => Signed(m, op.A!, 2, (short)m.Read(op.A!, 2) - 1L);

    public static void IncrementDouble(StlMachine m, StlOp op) => Signed(m, op.A!, 4, (int)m.Read(op.A!, 4) + 1L);

    public static void DecrementDouble(StlMachine m, StlOp op) => Signed(m, op.A!, 4, (int)m.Read(op.A!, 4) - 1L);

    /// <summary>MUL IN1, OUT: the low word of OUT times IN1, 16 x 16 bits into the 32-bit OUT (never overflows).</summary>
    public static void MultiplyToDouble(StlMachine m, StlOp op)
    {
        long product = (short)m.Read(op.A!, 2) * (long)(short)(m.Read(op.B!, 4) & 0xFFFF);
        Signed(m, op.B!, 4, product);
    }

    /// <summary>DIV IN1, OUT: the low word of OUT divided by IN1; OUT = remainder (high word) : quotient (low word).</summary>
    public static void DivideWithRemainder(StlMachine m, StlOp op)
    {
        var dividend = (short)(m.Read(op.B!, 4) & 0xFFFF);
        var divisor = (short)m.Read(op.A!, 2);
        if (divisor == 0)
        {
            DivisionByZero(m);
            return;
        }

        var quotient = dividend / divisor;
        var remainder = dividend % divisor;
        m.Write(op.B!, 4, ((uint)(ushort)remainder << 16) | (ushort)quotient);
        var overflow = quotient > short.MaxValue;
        m.SetFlags(Zero | Overflow | Negative | DivideByZero,
            (byte)((quotient == 0 ? Zero : 0) | (overflow ? Overflow : 0) | ((short)quotient < 0 ? Negative : 0)));
        m.Eno = !overflow;
    }

    /// <summary>Division by zero sets SM1.3 and ENO = 0 and leaves OUT unchanged.</summary>
    public static void DivisionByZero(StlMachine m)
    {
        m.SetFlags(Zero | Overflow | Negative | DivideByZero, DivideByZero);
        m.Eno = false;
    }

    /// <summary>Writes the wrapped result; SM1.1 when it does not fit (do not rely on the value then).</summary>
    private static void Signed(StlMachine m, StlLoc target, int bytes, long result)
    {
        var wrapped = bytes == 2 ? (short)result : (long)(int)result;
        m.Write(target, bytes, (uint)wrapped);
        m.SetFlags(Zero | Overflow | Negative,
            (byte)((wrapped == 0 ? Zero : 0) | (wrapped != result ? Overflow : 0) | (wrapped < 0 ? Negative : 0)));
        m.Eno &= wrapped == result;
    }

    /// <summary>INCB/DECB: bytes are unsigned; SM1.1 on the wrap from 255 to 0 or 0 to 255.</summary>
    private static void Unsigned(StlMachine m, StlLoc target, long result)
    {
        var wrapped = (byte)result;
        m.Write(target, 1, wrapped);
        m.SetFlags(Zero | Overflow, (byte)((wrapped == 0 ? Zero : 0) | (wrapped != result ? Overflow : 0)));
    }

    private static void Divide(StlMachine m, StlOp op, int bytes, long dividend, long divisor)
    {
        if (divisor == 0)
        {
            DivisionByZero(m);
            return;
        }

        Signed(m, op.B!, bytes, dividend / divisor);
        m.SetFlags(DivideByZero, 0);
    }
}
