namespace OperatorPanel.Core.Addressing;

/// <summary>How many bits an address covers.</summary>
public enum AccessWidth
{
    Bit,
    Byte,
    Word,
    DoubleWord,
}

public static class AccessWidthExtensions
{
    /// <summary>Bytes touched by one access of this width; a bit touches its one byte.</summary>
    public static int ByteCount(this AccessWidth width) => width switch
    {
        AccessWidth.Bit or AccessWidth.Byte => 1,
        AccessWidth.Word => 2,
        AccessWidth.DoubleWord => 4,
    };

    /// <summary>The manual's width letter: B, W or D ("" for a bit).</summary>
    public static string Letter(this AccessWidth width) => width switch
    {
        AccessWidth.Bit => "",
        AccessWidth.Byte => "B",
        AccessWidth.Word => "W",
        AccessWidth.DoubleWord => "D",
    };
}
