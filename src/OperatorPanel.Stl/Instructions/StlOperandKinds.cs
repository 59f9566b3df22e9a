namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// The operand kinds the manual's "Inputs/Outputs, Operands, Data Types" tables list for one operand: memory areas
/// (their width follows from the operand's <see cref="StlDataType"/>: V in a WORD operand means VW), the accumulators,
/// constants, indirect accesses through a pointer and the address-of operator.
/// </summary>
[Flags]
public enum StlOperandKinds
{
    None = 0,
    I = 1 << 0,
    Q = 1 << 1,
    M = 1 << 2,
    V = 1 << 3,
    SM = 1 << 4,
    S = 1 << 5,
    L = 1 << 6,

    /// <summary>A timer: its bit in a BOOL operand, its current value in a WORD/INT operand, the timer itself for TON.</summary>
    T = 1 << 7,

    /// <summary>A counter: its bit, its current value, or the counter itself for CTU.</summary>
    C = 1 << 8,

    /// <summary>A high-speed counter's current value (HC0-HC5, DINT).</summary>
    HC = 1 << 9,

    /// <summary>Analog input word AIW (read-only).</summary>
    AI = 1 << 10,

    /// <summary>Analog output word AQW (write-only).</summary>
    AQ = 1 << 11,

    AC = 1 << 12,

    /// <summary>A number, an ASCII constant ('A') or, for STRING operands, a string constant ("text").</summary>
    Constant = 1 << 13,

    /// <summary>*VD: the operand a pointer in a V double word points to.</summary>
    IndirectV = 1 << 14,

    /// <summary>*LD: the operand a pointer in an L double word points to.</summary>
    IndirectL = 1 << 15,

    /// <summary>*AC1-*AC3: the operand a pointer in an accumulator points to.</summary>
    IndirectAc = 1 << 16,

    /// <summary>&amp;VB100, &amp;IB0, &amp;T37 ...: the address of a byte, timer or counter (MOVD IN only).</summary>
    AddressOf = 1 << 17,

    /// <summary>A program organisation unit: SBR_n / INT_n, its name, or SBRn / INTn as exports write it.</summary>
    Pou = 1 << 18,
}
