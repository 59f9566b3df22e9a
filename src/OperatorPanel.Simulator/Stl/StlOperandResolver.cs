using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Checks;

namespace OperatorPanel.Simulator.Stl;

/// <summary>Turns a classified operand into a <see cref="StlLoc"/> for one operand position, checking width, writability and the CPU's ranges.</summary>
internal sealed class StlOperandResolver(CpuProfile cpu)
{
    public bool TryResolve(
        AwlOperand operand,
        StlOperandType type,
        IReadOnlyDictionary<string, (StlLoc Loc, int Bytes, bool IsBit)> locals,
        out StlLoc loc,
        out string error)
    {
        loc = null!;
        var bytes = BytesOf(type);
        var output = type is StlOperandType.BitOut or StlOperandType.ByteOut or StlOperandType.WordOut or StlOperandType.DWordOut;
        if (operand is { Kind: AwlOperandKind.Address, Area: MemoryArea.AC } && type is StlOperandType.ByteArea or StlOperandType.WordArea or StlOperandType.DWordArea)
        {
            error = $"'{operand.Text}': an accumulator cannot hold a buffer; use a memory address or *AC";
            return false;
        }

        if (type is StlOperandType.Timer or StlOperandType.Counter || operand is { Kind: AwlOperandKind.Address, Area: MemoryArea.T or MemoryArea.C })
        {
            return TryTimerOrCounter(operand, type, out loc, out error);
        }

        switch (operand.Kind)
        {
            case AwlOperandKind.Address:
                return TryAddress(operand, bytes, output, out loc, out error);
            case AwlOperandKind.Constant when type is StlOperandType.ByteIn or StlOperandType.WordIn or StlOperandType.DWordIn:
                return TryConstant(operand, bytes, out loc, out error);
            case AwlOperandKind.Constant when type is StlOperandType.SignedByteIn:
                return TrySignedByte(operand, out loc, out error);
            case AwlOperandKind.Pointer when type == StlOperandType.DWordIn:
                return TryPointer(operand, out loc, out error);
            case AwlOperandKind.Indirect when bytes > 0:
                return TryIndirect(operand, out loc, out error);
            case AwlOperandKind.Local:
                return TryLocal(operand, bytes, locals, out loc, out error);
            case AwlOperandKind.Symbol:
                error = $"'{operand.Text}' is not an address; the simulator reads absolute addresses and #locals (give the program's symbol table with --symbols)";
                return false;
            default:
                error = $"'{operand.Text}' cannot be used where a {Describe(type)} is expected";
                return false;
        }
    }

    /// <summary>0 for a bit, else the bytes of one access.</summary>
    public static int BytesOf(StlOperandType type) => type switch
    {
        StlOperandType.BitIn or StlOperandType.BitOut => 0,
        StlOperandType.ByteIn or StlOperandType.ByteOut or StlOperandType.ByteArea or StlOperandType.SignedByteIn => 1,
        StlOperandType.WordIn or StlOperandType.WordOut or StlOperandType.WordArea or StlOperandType.Timer or StlOperandType.Counter => 2,
        StlOperandType.DWordIn or StlOperandType.DWordOut or StlOperandType.DWordArea or StlOperandType.Label or StlOperandType.Block or StlOperandType.Event or StlOperandType.Port => 4,
    };

    /// <summary>
    /// T0-T255 and C0-C255 (System Manual A5E00307987-04, "Timer" and "Counter" operand tables): the box operand of a
    /// timer or counter, its bit where a bit is read or written (LD T37, R C1, 1), its current value where a word is
    /// (LDW&gt;= C1, 50, MOVW T37, VW0).
    /// </summary>
    private static bool TryTimerOrCounter(AwlOperand operand, StlOperandType type, out StlLoc loc, out string error)
    {
        loc = null!;
        var wanted = type switch
        {
            StlOperandType.Timer => MemoryArea.T,
            StlOperandType.Counter => MemoryArea.C,
            StlOperandType.BitIn or StlOperandType.BitOut or StlOperandType.ByteIn or StlOperandType.ByteOut or StlOperandType.WordIn or StlOperandType.WordOut or StlOperandType.DWordIn or StlOperandType.DWordOut or StlOperandType.ByteArea or StlOperandType.WordArea or StlOperandType.DWordArea or StlOperandType.Label or StlOperandType.Block or StlOperandType.Event or StlOperandType.Port or StlOperandType.SignedByteIn =>
                operand.Area,
        };
        var bytes = BytesOf(type);
        if (operand.Kind != AwlOperandKind.Address || operand.Area != wanted)
        {
            error = $"'{operand.Text}' is not a {(wanted == MemoryArea.T ? "timer (T0-T255)" : "counter (C0-C255)")}";
            return false;
        }

        if (operand.ByteOffset > 255)
        {
            error = $"'{operand.Text}': the S7-200 has {(wanted == MemoryArea.T ? "T0-T255" : "C0-C255")}";
            return false;
        }

        if (bytes is not (0 or 2) || type is StlOperandType.WordArea)
        {
            error = $"'{operand.Text}' is a bit or a word (current value); a {WidthName(bytes)} is expected here";
            return false;
        }

        error = string.Empty;
        loc = new StlLoc { Kind = wanted == MemoryArea.T ? StlLocKind.Timer : StlLocKind.Counter, Offset = operand.ByteOffset };
        return true;
    }

    /// <summary>SHRB's N: a signed length, written +4 or -14.</summary>
    private static bool TrySignedByte(AwlOperand operand, out StlLoc loc, out string error)
    {
        loc = null!;
        if (operand.ConstantKind != AwlConstantKind.Integer || operand.Integer is < sbyte.MinValue or > sbyte.MaxValue)
        {
            error = $"'{operand.Text}' is not a signed byte constant (-128 to +127)";
            return false;
        }

        error = string.Empty;
        loc = new StlLoc { Kind = StlLocKind.Constant, Value = (uint)(byte)(sbyte)operand.Integer };
        return true;
    }

    private bool TryAddress(AwlOperand operand, int bytes, bool output, out StlLoc loc, out string error)
    {
        loc = null!;
        if (operand.Area is MemoryArea.HC)
        {
            error = $"'{operand.Text}': high-speed counters are not implemented by the simulator (--strict)";
            return false;
        }

        if (operand.Area == MemoryArea.AC)
        {
            loc = new StlLoc { Kind = StlLocKind.Accumulator, Offset = operand.ByteOffset };
            error = bytes == 0 ? $"'{operand.Text}': an accumulator is not a bit"
                : operand.ByteOffset >= cpu.Accumulators ? $"'{operand.Text}': the CPU has AC0-AC{cpu.Accumulators - 1}" : string.Empty;
            return error.Length == 0;
        }

        var width = (operand.Width == AccessWidth.Bit ? 0 : operand.Width.ByteCount());
        if (width != bytes)
        {
            error = $"'{operand.Text}' is a {WidthName(width)}; a {WidthName(bytes)} is expected here";
            return false;
        }

        // The program check refuses the same (its line wins, StlProgramLoader); CALL's parameters reach only here.
        if (AwlCpuRanges.Check(operand, output, cpu) is { } refusal)
        {
            error = refusal.Message;
            return false;
        }

        error = string.Empty;
        loc = operand.Area == MemoryArea.L
            ? new StlLoc { Kind = StlLocKind.Local, Offset = operand.ByteOffset, Bit = operand.Bit ?? 0 }
            : new StlLoc { Kind = StlLocKind.Direct, Area = (int)operand.Area, Offset = operand.ByteOffset, Bit = operand.Bit ?? 0 };
        return true;
    }

    private static bool TryConstant(AwlOperand operand, int bytes, out StlLoc loc, out string error)
    {
        loc = null!;
        error = string.Empty;
        uint value;
        if (operand.ConstantKind == AwlConstantKind.Real && bytes == 4)
        {
            value = BitConverter.SingleToUInt32Bits((float)operand.Real);
        }
        else if (operand.ConstantKind == AwlConstantKind.Integer && Fits(operand.Integer, bytes))
        {
            value = (uint)operand.Integer;
        }
        else if (operand.ConstantKind == AwlConstantKind.Ascii && operand.Name.Length <= bytes)
        {
            // 'A', 'OK', 'STOP': one byte per character, the first character the most significant (the parser's value).
            value = (uint)operand.Integer;
        }
        else
        {
            error = $"'{operand.Text}' is not a {WidthName(bytes)} constant";
            return false;
        }

        loc = new StlLoc { Kind = StlLocKind.Constant, Value = value };
        return true;
    }

    private static bool Fits(long value, int bytes) => bytes switch
    {
        1 => value is >= 0 and <= 255,
        2 => value is >= short.MinValue and <= ushort.MaxValue,
        _ => value is >= int.MinValue and <= uint.MaxValue,
    };

    private bool TryPointer(AwlOperand operand, out StlLoc loc, out string error)
    {
        loc = null!;
        if (operand.Area is not (MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.SM or MemoryArea.S))
        {
            error = $"'{operand.Text}': the simulator takes pointers to I, Q, M, V, SM and S bytes only";
            return false;
        }

        if (AwlCpuRanges.Check(operand, written: false, cpu) is { } refusal)
        {
            error = refusal.Message;
            return false;
        }

        error = string.Empty;
        loc = new StlLoc { Kind = StlLocKind.Constant, Value = StlPointer.Encode(operand.Area, operand.ByteOffset) };
        return true;
    }

    private bool TryIndirect(AwlOperand operand, out StlLoc loc, out string error)
    {
        loc = null!;
        var holderOperand = operand with { Kind = AwlOperandKind.Address };
        if (!TryAddress(holderOperand, 4, output: false, out var holder, out error))
        {
            return false;
        }

        loc = new StlLoc { Kind = StlLocKind.Indirect, Holder = holder };
        return true;
    }

    private static bool TryLocal(
        AwlOperand operand,
        int bytes,
        IReadOnlyDictionary<string, (StlLoc Loc, int Bytes, bool IsBit)> locals,
        out StlLoc loc,
        out string error)
    {
        loc = null!;
        if (!locals.TryGetValue(operand.Name, out var local))
        {
            error = $"'{operand.Text}' is not declared in this block's variable table";
            return false;
        }

        var width = local.IsBit ? 0 : local.Bytes;
        if (width != bytes)
        {
            error = $"'{operand.Text}' is a {WidthName(width)}; a {WidthName(bytes)} is expected here";
            return false;
        }

        error = string.Empty;
        loc = local.Loc;
        return true;
    }

    private static string WidthName(int bytes) => bytes switch
    {
        0 => "bit",
        1 => "byte",
        2 => "word",
        _ => "double word",
    };

    private static string Describe(StlOperandType type) => type switch
    {
        StlOperandType.ByteArea or StlOperandType.WordArea or StlOperandType.DWordArea => $"{WidthName(BytesOf(type))} in memory",
        StlOperandType.BitOut or StlOperandType.ByteOut or StlOperandType.WordOut or StlOperandType.DWordOut =>
            $"writable {WidthName(BytesOf(type))}",
        StlOperandType.BitIn or StlOperandType.ByteIn or StlOperandType.WordIn or StlOperandType.DWordIn or StlOperandType.SignedByteIn or StlOperandType.Label or StlOperandType.Block or StlOperandType.Event or StlOperandType.Port or StlOperandType.Timer or StlOperandType.Counter =>
            WidthName(BytesOf(type)),
    };
}
