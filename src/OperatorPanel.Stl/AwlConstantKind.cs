namespace OperatorPanel.Stl;

/// <summary>How a constant operand was written.</summary>
public enum AwlConstantKind
{
    /// <summary>Decimal, 16# hexadecimal or 2# binary integer.</summary>
    Integer,

    /// <summary>A real number with a decimal point or exponent.</summary>
    Real,

    /// <summary>A string constant in double quotes, "AB" (string instructions only).</summary>
    String,

    /// <summary>
    /// An ASCII constant in single quotes, 'A' or 'AB' (System Manual 08/2008 Table 4-2 "Representation of constant
    /// values"): one byte per character, so <see cref="AwlOperand.Integer"/> holds 'AB' as 16#4142 when it fits 4 bytes.
    /// </summary>
    Ascii,
}
