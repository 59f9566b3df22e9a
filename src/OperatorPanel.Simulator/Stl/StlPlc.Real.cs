namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// MUL/DIV and IEEE single real arithmetic (A5E00307987-04 chapter 6, "Math Instructions"): STL form OUT = OUT op IN1
/// (+R, *R; -R and /R subtract and divide IN1 from OUT). SM1.0 zero, SM1.1 overflow or an illegal value (NaN or
/// infinity) produced, SM1.2 negative, SM1.3 division by zero; an error sets ENO = 0, and a division by zero leaves
/// OUT unchanged. Real compares (LDR=, AR&lt;, OR&gt;= ...) compare the two reals.
/// </summary>
public sealed partial class StlPlc
{
    private void WideArithmetic(StlOp op)
    {
        switch (op.Code)
        {
            case StlOpCode.Mul: Multiply(op); break;
            case StlOpCode.Div: DivideWithRemainder(op); break;
            case StlOpCode.AddR: RealResult(op.B!, ReadReal(op.B!) + ReadReal(op.A!)); break;
            case StlOpCode.SubR: RealResult(op.B!, ReadReal(op.B!) - ReadReal(op.A!)); break;
            case StlOpCode.MulR: RealResult(op.B!, ReadReal(op.B!) * ReadReal(op.A!)); break;
            case StlOpCode.DivR: RealDivide(op); break;
            case StlOpCode.Sqrt: RealResult(op.B!, MathF.Sqrt(ReadReal(op.A!))); break;
            case StlOpCode.Ln: RealResult(op.B!, MathF.Log(ReadReal(op.A!))); break;
            case StlOpCode.Exp: RealResult(op.B!, MathF.Exp(ReadReal(op.A!))); break;
            case StlOpCode.Sin: RealResult(op.B!, MathF.Sin(ReadReal(op.A!))); break;
            case StlOpCode.Cos: RealResult(op.B!, MathF.Cos(ReadReal(op.A!))); break;
            case StlOpCode.Tan: RealResult(op.B!, MathF.Tan(ReadReal(op.A!))); break;
            default: Convert(op); break;
        }
    }

    private float ReadReal(StlLoc loc) => BitConverter.UInt32BitsToSingle(Read(loc, 4));

    /// <summary>MUL IN1, OUT: the low word of OUT times IN1, 16 x 16 bits into the 32-bit OUT (never overflows).</summary>
    private void Multiply(StlOp op)
    {
        long product = (short)Read(op.A!, 2) * (long)(short)(Read(op.B!, 4) & 0xFFFF);
        SignedTo(op.B!, 4, product);
    }

    /// <summary>DIV IN1, OUT: the low word of OUT divided by IN1; OUT = remainder (high word) : quotient (low word).</summary>
    private void DivideWithRemainder(StlOp op)
    {
        var dividend = (short)(Read(op.B!, 4) & 0xFFFF);
        var divisor = (short)Read(op.A!, 2);
        if (divisor == 0)
        {
            SetFlags(Zero | Overflow | Negative | DivideByZero, DivideByZero);
            _eno = false;
            return;
        }

        var quotient = dividend / divisor;
        var remainder = dividend % divisor;
        Write(op.B!, 4, ((uint)(ushort)remainder << 16) | (ushort)quotient);
        var overflow = quotient > short.MaxValue;
        SetFlags(Zero | Overflow | Negative | DivideByZero,
            (byte)((quotient == 0 ? Zero : 0) | (overflow ? Overflow : 0) | ((short)quotient < 0 ? Negative : 0)));
        _eno = !overflow;
    }

    private void RealDivide(StlOp op)
    {
        var divisor = ReadReal(op.A!);
        if (divisor == 0)
        {
            SetFlags(Zero | Overflow | Negative | DivideByZero, DivideByZero);
            _eno = false;
            return;
        }

        RealResult(op.B!, ReadReal(op.B!) / divisor);
    }

    /// <summary>Writes the result; NaN or infinity sets SM1.1 (the negative flag is then not valid) and ENO = 0.</summary>
    private void RealResult(StlLoc target, float result)
    {
        Write(target, 4, BitConverter.SingleToUInt32Bits(result));
        var illegal = !float.IsFinite(result);
        SetFlags(Zero | Overflow | Negative | DivideByZero,
            (byte)((result == 0 ? Zero : 0) | (illegal ? Overflow : 0) | (!illegal && result < 0 ? Negative : 0)));
        _eno = !illegal;
    }

    private bool CompareReal(StlOp op)
    {
        var a = ReadReal(op.A!);
        var b = ReadReal(op.B!);
        return Holds(op.N, a, b);
    }
}
