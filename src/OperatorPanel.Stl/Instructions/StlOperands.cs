using static OperatorPanel.Stl.Instructions.StlOperandKinds;

namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// The operand kind sets the manual's tables repeat, and builders for operands of each kind. "Memory" sets have no
/// accumulator and no constant: the operand is the start of something in memory (a block, a table, a string).
/// </summary>
public static class StlOperands
{
    public const StlOperandKinds Indirect = IndirectV | IndirectL | IndirectAc;

    /// <summary>BOOL: I, Q, V, M, SM, S, T, C, L (LD, A, O, =, S, R, SHRB).</summary>
    public const StlOperandKinds Bits = I | Q | V | M | SM | S | T | C | L;

    /// <summary>IB, QB, VB, MB, SMB, SB, LB, *VD, *LD, *AC.</summary>
    public const StlOperandKinds ByteMemory = I | Q | V | M | SM | S | L | Indirect;

    /// <summary>IB, QB, VB, MB, SMB, SB, LB, AC, *VD, *LD, *AC.</summary>
    public const StlOperandKinds ByteOutKinds = ByteMemory | AC;

    /// <summary>IB, QB, VB, MB, SMB, SB, LB, AC, *VD, *LD, *AC, constant.</summary>
    public const StlOperandKinds ByteInKinds = ByteOutKinds | Constant;

    /// <summary>IW, QW, VW, MW, SMW, SW, T, C, LW, *VD, *LD, *AC.</summary>
    public const StlOperandKinds WordMemory = I | Q | V | M | SM | S | T | C | L | Indirect;

    /// <summary>IW, QW, VW, MW, SMW, SW, T, C, LW, AC, AIW, *VD, *LD, *AC, constant.</summary>
    public const StlOperandKinds WordInKinds = WordMemory | AC | AI | Constant;

    /// <summary>IW, QW, VW, MW, SMW, SW, T, C, LW, AC, *VD, *LD, *AC: an OUT that STL also reads (OUT = OUT op IN).</summary>
    public const StlOperandKinds WordInOutKinds = WordMemory | AC;

    /// <summary>IW, QW, VW, MW, SMW, SW, T, C, LW, AQW, AC, *VD, *LD, *AC: an OUT only written (MOVW, BTI).</summary>
    public const StlOperandKinds WordOutKinds = WordMemory | AC | AQ;

    /// <summary>ID, QD, VD, MD, SMD, SD, LD, *VD, *LD, *AC.</summary>
    public const StlOperandKinds DWordMemory = I | Q | V | M | SM | S | L | Indirect;

    /// <summary>ID, QD, VD, MD, SMD, SD, LD, AC, *VD, *LD, *AC.</summary>
    public const StlOperandKinds DWordOutKinds = DWordMemory | AC;

    /// <summary>ID, QD, VD, MD, SMD, SD, LD, HC, AC, *VD, *LD, *AC, constant.</summary>
    public const StlOperandKinds DWordInKinds = DWordOutKinds | HC | Constant;

    /// <summary>ID, QD, VD, MD, SMD, SD, LD, AC, *VD, *LD, *AC, constant.</summary>
    public const StlOperandKinds RealInKinds = DWordOutKinds | Constant;

    /// <summary>VB, LB, *VD, *LD, *AC: where a string may lie.</summary>
    public const StlOperandKinds StringMemory = V | L | Indirect;

    public static StlOperandSpec BitIn(string name = "bit") => new(name, StlDataType.Bool, Bits, StlAccess.Read);

    public static StlOperandSpec BitOut(string name = "bit") => new(name, StlDataType.Bool, Bits, StlAccess.Write);

    public static StlOperandSpec ByteIn(string name) => new(name, StlDataType.Byte, ByteInKinds, StlAccess.Read);

    public static StlOperandSpec ByteOut(string name) => new(name, StlDataType.Byte, ByteOutKinds, StlAccess.Write);

    public static StlOperandSpec ByteInOut(string name) => new(name, StlDataType.Byte, ByteOutKinds, StlAccess.ReadWrite);

    public static StlOperandSpec ByteArea(string name, StlAccess access) => new(name, StlDataType.Byte, ByteMemory, access);

    public static StlOperandSpec Count(string name = "N") => ByteIn(name).Range(1, 255);

    public static StlOperandSpec WordIn(string name, StlDataType type = StlDataType.Int) => new(name, type, WordInKinds, StlAccess.Read);

    public static StlOperandSpec WordOut(string name, StlDataType type = StlDataType.Int) => new(name, type, WordOutKinds, StlAccess.Write);

    public static StlOperandSpec WordInOut(string name, StlDataType type = StlDataType.Int) => new(name, type, WordInOutKinds, StlAccess.ReadWrite);

    public static StlOperandSpec DWordIn(string name, StlDataType type = StlDataType.DInt) => new(name, type, DWordInKinds, StlAccess.Read);

    public static StlOperandSpec DWordOut(string name, StlDataType type = StlDataType.DInt) => new(name, type, DWordOutKinds, StlAccess.Write);

    public static StlOperandSpec DWordInOut(string name, StlDataType type = StlDataType.DInt) => new(name, type, DWordOutKinds, StlAccess.ReadWrite);

    public static StlOperandSpec RealIn(string name) => new(name, StlDataType.Real, RealInKinds, StlAccess.Read);

    public static StlOperandSpec RealOut(string name) => new(name, StlDataType.Real, DWordOutKinds, StlAccess.Write);

    public static StlOperandSpec RealInOut(string name) => new(name, StlDataType.Real, DWordOutKinds, StlAccess.ReadWrite);

    public static StlOperandSpec StringIn(string name) => new(name, StlDataType.String, StringMemory | Constant, StlAccess.Read);

    public static StlOperandSpec StringArea(string name, StlAccess access) => new(name, StlDataType.String, StringMemory, access);

    /// <summary>A constant of a special kind: label, event, port, or a plain BYTE/WORD constant (HSC number, PID loop).</summary>
    public static StlOperandSpec Number(string name, StlDataType type, long min, long max) =>
        new StlOperandSpec(name, type, Constant, StlAccess.Read).Range(min, max);
}
