namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>The bits of SMB1, the instruction status byte (seed 002, Table C-2).</summary>
internal static class StatusBits
{
    /// <summary>SM1.0: the result is zero.</summary>
    public const byte Zero = 0x01;

    /// <summary>SM1.1: overflow, an illegal value, or the last bit shifted or rotated out.</summary>
    public const byte Overflow = 0x02;

    /// <summary>SM1.2: the result is negative.</summary>
    public const byte Negative = 0x04;

    /// <summary>SM1.3: division by zero.</summary>
    public const byte DivideByZero = 0x08;

    /// <summary>SM1.4: ATT on a full table.</summary>
    public const byte TableFull = 0x10;

    /// <summary>SM1.5: FIFO/LIFO on an empty table.</summary>
    public const byte TableEmpty = 0x20;

    /// <summary>SM1.6: a digit that is not BCD.</summary>
    public const byte InvalidBcd = 0x40;

    /// <summary>SM1.7: a character that is not ASCII hex.</summary>
    public const byte IllegalAscii = 0x80;
}
