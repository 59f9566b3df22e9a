namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Integer arithmetic, conversions, logic and shifts (STL form OUT = OUT op IN) with the SMB1 flags: SM1.0 zero,
/// SM1.1 overflow (or last bit shifted out), SM1.2 negative, SM1.3 division by zero (seed 002, Table C-2).
/// </summary>
public sealed partial class StlPlc
{
    private const byte Zero = 0x01;
    private const byte Overflow = 0x02;
    private const byte Negative = 0x04;
    private const byte DivideByZero = 0x08;
    private const byte IllegalAscii = 0x80;

    private void Arithmetic(StlOp op)
    {
        switch (op.Code)
        {
            case StlOpCode.AddI: Signed(op, 2, (long)(short)Read(op.B!, 2) + (short)Read(op.A!, 2)); break;
            case StlOpCode.SubI: Signed(op, 2, (long)(short)Read(op.B!, 2) - (short)Read(op.A!, 2)); break;
            case StlOpCode.MulI: Signed(op, 2, (long)(short)Read(op.B!, 2) * (short)Read(op.A!, 2)); break;
            case StlOpCode.DivI: Divide(op, 2, (short)Read(op.B!, 2), (short)Read(op.A!, 2)); break;
            case StlOpCode.AddD: Signed(op, 4, (long)(int)Read(op.B!, 4) + (int)Read(op.A!, 4)); break;
            case StlOpCode.SubD: Signed(op, 4, (long)(int)Read(op.B!, 4) - (int)Read(op.A!, 4)); break;
            case StlOpCode.MulD: Signed(op, 4, (long)(int)Read(op.B!, 4) * (int)Read(op.A!, 4)); break;
            case StlOpCode.DivD: Divide(op, 4, (int)Read(op.B!, 4), (int)Read(op.A!, 4)); break;
            case StlOpCode.IncB: Unsigned(op.A!, Read(op.A!, 1) + 1L); break;
            case StlOpCode.DecB: Unsigned(op.A!, Read(op.A!, 1) - 1L); break;
            case StlOpCode.IncW: SignedTo(op.A!, 2, (short)Read(op.A!, 2) + 1L); break;
            case StlOpCode.DecW: SignedTo(op.A!, 2, (short)Read(op.A!, 2) - 1L); break;
            case StlOpCode.IncD: SignedTo(op.A!, 4, (int)Read(op.A!, 4) + 1L); break;
            case StlOpCode.DecD: SignedTo(op.A!, 4, (int)Read(op.A!, 4) - 1L); break;
            case StlOpCode.Bti: Write(op.B!, 2, Read(op.A!, 1)); break;
            case StlOpCode.Itd: Write(op.B!, 4, (uint)(int)(short)Read(op.A!, 2)); break;
            case StlOpCode.Itb: Narrow(op.B!, 1, (short)Read(op.A!, 2), 0, 255); break;
            case StlOpCode.Dti: Narrow(op.B!, 2, (int)Read(op.A!, 4), short.MinValue, short.MaxValue); break;
            case StlOpCode.AndB: Logic(op.B!, 1, Read(op.A!, 1) & Read(op.B!, 1)); break;
            case StlOpCode.OrB: Logic(op.B!, 1, Read(op.A!, 1) | Read(op.B!, 1)); break;
            case StlOpCode.XorB: Logic(op.B!, 1, Read(op.A!, 1) ^ Read(op.B!, 1)); break;
            case StlOpCode.InvB: Logic(op.A!, 1, ~Read(op.A!, 1)); break;
            case StlOpCode.AndW: Logic(op.B!, 2, Read(op.A!, 2) & Read(op.B!, 2)); break;
            case StlOpCode.OrW: Logic(op.B!, 2, Read(op.A!, 2) | Read(op.B!, 2)); break;
            case StlOpCode.XorW: Logic(op.B!, 2, Read(op.A!, 2) ^ Read(op.B!, 2)); break;
            case StlOpCode.InvW: Logic(op.A!, 2, ~Read(op.A!, 2)); break;
            case StlOpCode.AndD: Logic(op.B!, 4, Read(op.A!, 4) & Read(op.B!, 4)); break;
            case StlOpCode.OrD: Logic(op.B!, 4, Read(op.A!, 4) | Read(op.B!, 4)); break;
            case StlOpCode.XorD: Logic(op.B!, 4, Read(op.A!, 4) ^ Read(op.B!, 4)); break;
            case StlOpCode.InvD: Logic(op.A!, 4, ~Read(op.A!, 4)); break;
            case StlOpCode.Slb: Shift(op, 1, left: true); break;
            case StlOpCode.Srb: Shift(op, 1, left: false); break;
            case StlOpCode.Slw: Shift(op, 2, left: true); break;
            case StlOpCode.Srw: Shift(op, 2, left: false); break;
            case StlOpCode.Sld: Shift(op, 4, left: true); break;
            case StlOpCode.Srd: Shift(op, 4, left: false); break;
            default: WideArithmetic(op); break;
        }
    }

    private ref byte Flags => ref _areas[(int)Core.Addressing.MemoryArea.SM][1];

    private void SetFlags(byte mask, byte value) => Flags = (byte)((Flags & ~mask) | value);

    private void Signed(StlOp op, int bytes, long result) => SignedTo(op.B!, bytes, result);

    /// <summary>Writes the wrapped result; SM1.1 when it does not fit (do not rely on the value then).</summary>
    private void SignedTo(StlLoc target, int bytes, long result)
    {
        var wrapped = bytes == 2 ? (short)result : (long)(int)result;
        Write(target, bytes, (uint)wrapped);
        SetFlags(Zero | Overflow | Negative,
            (byte)((wrapped == 0 ? Zero : 0) | (wrapped != result ? Overflow : 0) | (wrapped < 0 ? Negative : 0)));
        _eno &= wrapped == result;
    }

    /// <summary>INCB/DECB: bytes are unsigned; SM1.1 on the wrap from 255 to 0 or 0 to 255.</summary>
    private void Unsigned(StlLoc target, long result)
    {
        var wrapped = (byte)result;
        Write(target, 1, wrapped);
        SetFlags(Zero | Overflow, (byte)((wrapped == 0 ? Zero : 0) | (wrapped != result ? Overflow : 0)));
    }

    /// <summary>Division by zero sets SM1.3 and leaves OUT unchanged.</summary>
    private void Divide(StlOp op, int bytes, long dividend, long divisor)
    {
        if (divisor == 0)
        {
            SetFlags(Zero | Overflow | Negative | DivideByZero, DivideByZero);
            _eno = false;
            return;
        }

        SignedTo(op.B!, bytes, dividend / divisor);
        SetFlags(DivideByZero, 0);
    }

    /// <summary>ITB/DTI: a value that does not fit sets SM1.1 and the output is not affected.</summary>
    private void Narrow(StlLoc target, int bytes, long value, long min, long max)
    {
        if (value < min || value > max)
        {
            SetFlags(Overflow, Overflow);
            _eno = false;
            return;
        }

        Write(target, bytes, (uint)value);
        SetFlags(Overflow, 0);
    }

    private void Logic(StlLoc target, int bytes, uint value)
    {
        value &= Mask(bytes);
        Write(target, bytes, value);
        SetFlags(Zero, value == 0 ? Zero : (byte)0);
    }

    /// <summary>SHL/SHR OUT, N: N above the width shifts by the width; SM1.1 is the last bit shifted out.</summary>
    private void Shift(StlOp op, int bytes, bool left)
    {
        var bits = bytes * 8;
        var count = Math.Min((int)Read(op.B!, 1), bits);
        var value = (ulong)Read(op.A!, bytes);
        if (count == 0)
        {
            SetFlags(Zero, value == 0 ? Zero : (byte)0);
            return;
        }

        var lastOut = left ? (value >> (bits - count)) & 1 : (value >> (count - 1)) & 1;
        var result = (uint)((left ? value << count : value >> count) & Mask(bytes));
        Write(op.A!, bytes, result);
        SetFlags(Zero | Overflow, (byte)((result == 0 ? Zero : 0) | (lastOut != 0 ? Overflow : 0)));
    }
}
