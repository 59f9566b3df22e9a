using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Projects;

/// <summary>Which display formats fit which address widths.</summary>
public static class DisplayFormats
{
    /// <summary>True when <paramref name="format"/> can show a value of <paramref name="width"/>.</summary>
    public static bool Fits(this DisplayFormat format, AccessWidth width) => format switch
    {
        DisplayFormat.Bool => width == AccessWidth.Bit,
        DisplayFormat.Float => width == AccessWidth.DoubleWord,
        DisplayFormat.Unsigned or DisplayFormat.Signed or DisplayFormat.Hex or DisplayFormat.Binary or DisplayFormat.Ascii => width != AccessWidth.Bit,
    };

    /// <summary>The format a tag gets when its file entry names none: Bool for a bit, Unsigned otherwise.</summary>
    public static DisplayFormat DefaultFor(AccessWidth width) =>
        width == AccessWidth.Bit ? DisplayFormat.Bool : DisplayFormat.Unsigned;

    /// <summary>
    /// The format of a tag at <paramref name="address"/> whose entry names none: Signed for analog words and timer and
    /// counter current values, which the CPU holds as signed integers (a bipolar input, a counter counting down); else
    /// by width.
    /// </summary>
    public static DisplayFormat DefaultFor(PlcAddress address) =>
        address.Area is MemoryArea.AI or MemoryArea.AQ or MemoryArea.T or MemoryArea.C ? DisplayFormat.Signed : DefaultFor(address.Width);
}
