namespace OperatorPanel.Stl.Instructions;

/// <summary>What the instruction does with one operand. STL writes OUT = OUT op IN, so many OUT operands are read too.</summary>
public enum StlAccess
{
    Read,
    Write,

    /// <summary>Read and written: +I IN, OUT (OUT = IN + OUT), INCB OUT, SLB OUT, N, the table of ATT/FIFO.</summary>
    ReadWrite,
}
