namespace OperatorPanel.Stl.Instructions;

/// <summary>Why an operand does not fit its position.</summary>
public enum StlRefusalKind
{
    /// <summary>Wrong kind or size: a byte where a word belongs, a constant as OUT, AQW as IN.</summary>
    Kind,

    /// <summary>A constant or number outside the position's range: label 256, N = 0 for S/R, T256.</summary>
    OutOfRange,
}
