using OperatorPanel.Simulator.Stl.Execution;
using static OperatorPanel.Simulator.Stl.Operations.StatusBits;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// IEEE single real arithmetic (A5E00307987-04 chapter 6, "Math Instructions"): STL form OUT = OUT op IN1 (+R, *R;
/// -R and /R subtract and divide IN1 from OUT). SM1.0 zero, SM1.1 overflow or an illegal value (NaN or infinity)
/// produced, SM1.2 negative, SM1.3 division by zero; an error sets ENO = 0, and a division by zero leaves OUT unchanged.
/// </summary>
internal static class RealMathInstructions
{
    public static void Add(StlMachine m, StlOp op) => Result(m, op.B!, m.ReadReal(op.B!) + m.ReadReal(op.A!));

    public static void Subtract(StlMachine m, StlOp op) => Result(m, op.B!, m.ReadReal(op.B!) - m.ReadReal(op.A!));

    public static void Multiply(StlMachine m, StlOp op) => Result(m, op.B!, m.ReadReal(op.B!) * m.ReadReal(op.A!));

    public static void Divide(StlMachine m, StlOp op)
    {
        var divisor = m.ReadReal(op.A!);
        if (divisor == 0)
        {
            IntegerMathInstructions.DivisionByZero(m);
            return;
        }

        Result(m, op.B!, m.ReadReal(op.B!) / divisor);
    }

    public static void SquareRoot(StlMachine m, StlOp op) => Result(m, op.B!, MathF.Sqrt(m.ReadReal(op.A!)));

    public static void NaturalLogarithm(StlMachine m, StlOp op) => Result(m, op.B!, MathF.Log(m.ReadReal(op.A!)));

    public static void Exponential(StlMachine m, StlOp op) => Result(m, op.B!, MathF.Exp(m.ReadReal(op.A!)));

    public static void Sine(StlMachine m, StlOp op) => Result(m, op.B!, MathF.Sin(m.ReadReal(op.A!)));

    public static void Cosine(StlMachine m, StlOp op) => Result(m, op.B!, MathF.Cos(m.ReadReal(op.A!)));

    public static void Tangent(StlMachine m, StlOp op) => Result(m, op.B!, MathF.Tan(m.ReadReal(op.A!)));

    /// <summary>Writes the result; NaN or infinity sets SM1.1 (the negative flag is then not valid) and ENO = 0.</summary>
    private static void Result(StlMachine m, StlLoc target, float result)
    {
        m.Write(target, 4, BitConverter.SingleToUInt32Bits(result));
        var illegal = !float.IsFinite(result);
        m.SetFlags(Zero | Overflow | Negative | DivideByZero,
            (byte)((result == 0 ? Zero : 0) | (illegal ? Overflow : 0) | (!illegal && result < 0 ? Negative : 0)));
        m.Eno = !illegal;
    }
}
