namespace OperatorPanel.Stl.Instructions;

/// <summary>How many elements of its data type an operand covers, given the instruction's count operand n.</summary>
public enum StlExtent
{
    /// <summary>One element: the operand itself.</summary>
    One,

    /// <summary>n elements from the operand (BMB IN, OUT; S bit, N; FILL OUT).</summary>
    Count,

    /// <summary>(n + 1) / 2 bytes: the packed digits of ATH OUT and HTA IN.</summary>
    HalfCount,

    /// <summary>|n| bits (SHRB S_BIT: a negative N shifts the other way over the same length).</summary>
    AbsoluteCount,
}
