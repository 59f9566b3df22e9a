using OperatorPanel.Simulator.Stl.Execution;
using static OperatorPanel.Simulator.Stl.Operations.StatusBits;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>ANDx, ORx, XORx IN, OUT (OUT = OUT op IN) and INVx OUT, on bytes, words and double words; SM1.0 when the result is zero.</summary>
internal static class LogicalInstructions
{
    public static StlHandler And(int bytes) => (m, op) => Result(m, op.B!, bytes, m.Read(op.A!, bytes) & m.Read(op.B!, bytes));

    public static StlHandler Or(int bytes) => (m, op) => Result(m, op.B!, bytes, m.Read(op.A!, bytes) | m.Read(op.B!, bytes));

    public static StlHandler Xor(int bytes) => (m, op) => Result(m, op.B!, bytes, m.Read(op.A!, bytes) ^ m.Read(op.B!, bytes));

    public static StlHandler Invert(int bytes) => (m, op) => Result(m, op.A!, bytes, ~m.Read(op.A!, bytes));

    private static void Result(StlMachine m, StlLoc target, int bytes, uint value)
    {
        value &= StlMachine.Mask(bytes);
        m.Write(target, bytes, value);
        m.SetFlags(Zero, value == 0 ? Zero : (byte)0);
    }
}
