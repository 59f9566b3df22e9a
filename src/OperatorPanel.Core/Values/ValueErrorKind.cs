namespace OperatorPanel.Core.Values;

/// <summary>Why a value typed by the operator was refused.</summary>
public enum ValueErrorKind
{
    /// <summary>Nothing but blanks.</summary>
    Empty,

    /// <summary>Not written in the notation the format reads (e.g. letters in a decimal number).</summary>
    Malformed,

    /// <summary>
    /// A number outside what the address's width holds in that format; for a REAL, one too large or so close to 0 that
    /// single precision would store it as 0 or as a denormal (ValueParser.Real.cs).
    /// </summary>
    OutOfRange,

    /// <summary>ASCII text that is not exactly as long as the address is wide.</summary>
    WrongLength,

    /// <summary>ASCII text with a character outside printable ASCII (space to ~).</summary>
    NotAscii,

    /// <summary>NaN or Infinity typed for a REAL: no number at all.</summary>
    NotFinite,

    /// <summary>The format cannot hold a value of the address's width (Float on a word, Bool on a byte).</summary>
    FormatDoesNotFit,
}
