namespace OperatorPanel.Core.Values;

/// <summary>Why a value typed by the operator was refused.</summary>
public enum ValueErrorKind
{
    /// <summary>Nothing but blanks.</summary>
    Empty,

    /// <summary>Not written in the notation the format reads (e.g. letters in a decimal number).</summary>
    Malformed,

    /// <summary>A number outside what the address's width holds in that format.</summary>
    OutOfRange,

    /// <summary>ASCII text that is not exactly as long as the address is wide.</summary>
    WrongLength,

    /// <summary>ASCII text with a character outside printable ASCII (space to ~).</summary>
    NotAscii,

    /// <summary>A REAL that is infinite or not a number once stored as IEEE 754 single precision.</summary>
    NotFinite,

    /// <summary>The format cannot hold a value of the address's width (Float on a word, Bool on a byte).</summary>
    FormatDoesNotFit,
}
