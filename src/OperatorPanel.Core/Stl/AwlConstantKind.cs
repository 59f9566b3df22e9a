namespace OperatorPanel.Core.Stl;

/// <summary>How a constant operand was written.</summary>
public enum AwlConstantKind
{
    /// <summary>Decimal, 16# hexadecimal or 2# binary integer.</summary>
    Integer,

    /// <summary>A real number with a decimal point or exponent.</summary>
    Real,

    /// <summary>A quoted string: 'AB' or "AB".</summary>
    String,
}
