namespace OperatorPanel.Stl.Instructions;

/// <summary>The SMB1 status bits an instruction sets or clears (manual Appendix D, SMB1).</summary>
[Flags]
public enum StlStatusBits
{
    None = 0,

    /// <summary>SM1.0: the result is zero.</summary>
    Zero = 1 << 0,

    /// <summary>SM1.1: overflow, or an illegal value (real math, conversions).</summary>
    Overflow = 1 << 1,

    /// <summary>SM1.2: the result is negative.</summary>
    Negative = 1 << 2,

    /// <summary>SM1.3: division by zero.</summary>
    DivideByZero = 1 << 3,

    /// <summary>SM1.4: ATT into a full table.</summary>
    TableFull = 1 << 4,

    /// <summary>SM1.5: FIFO/LIFO from an empty table.</summary>
    TableEmpty = 1 << 5,

    /// <summary>SM1.6: a BCD/binary conversion of an illegal value.</summary>
    BcdError = 1 << 6,

    /// <summary>SM1.7: an ASCII character that is not a hex digit.</summary>
    AsciiError = 1 << 7,
}
