namespace OperatorPanel.Core.Projects;

/// <summary>How the panel shows a memory cell's value.</summary>
public enum DisplayFormat
{
    /// <summary>A bit as 0/1; bits only.</summary>
    Bool,

    /// <summary>Unsigned decimal; bytes, words and double words.</summary>
    Unsigned,

    /// <summary>Two's-complement decimal (INT, DINT); bytes, words and double words.</summary>
    Signed,

    /// <summary>Hexadecimal as STL writes it (16#0A3F).</summary>
    Hex,

    /// <summary>Binary as STL writes it (2#0000_1010).</summary>
    Binary,

    /// <summary>IEEE 754 single precision (REAL); double words only.</summary>
    Float,

    /// <summary>The bytes as ASCII characters, most significant byte first; bytes, words and double words.</summary>
    Ascii,
}
