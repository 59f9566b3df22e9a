namespace OperatorPanel.Core.Ppi;

/// <summary>Why bytes that began like a telegram were not one (<see cref="PpiFrameReader"/>).</summary>
public enum PpiFrameError
{
    None,

    /// <summary>The sum of DA..data modulo 256 differs from the FCS character.</summary>
    ChecksumMismatch,

    /// <summary>The character where 16#16 belongs is something else.</summary>
    BadEnd,

    /// <summary>An SD2 header whose LE and LEr differ, or whose second delimiter is not 16#68.</summary>
    BadHeader,

    /// <summary>An SD2 length outside 4-249.</summary>
    LengthOutOfRange,
}
