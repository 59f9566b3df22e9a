namespace OperatorPanel.Core.Addressing;

/// <summary>How each area is written in STL: its prefix and the widths it takes.</summary>
internal static class AreaSyntax
{
    /// <summary>Prefixes the panel parses, longest first so "SM" wins over "S" and "AI" over nothing.</summary>
    public static readonly (string Prefix, MemoryArea Area)[] Parsed =
    [
        ("SM", MemoryArea.SM),
        ("AI", MemoryArea.AI),
        ("AQ", MemoryArea.AQ),
        ("I", MemoryArea.I),
        ("Q", MemoryArea.Q),
        ("M", MemoryArea.M),
        ("V", MemoryArea.V),
        ("S", MemoryArea.S),
        ("T", MemoryArea.T),
        ("C", MemoryArea.C),
    ];

    /// <summary>Areas that exist on the CPU but are not addressed by byte number in the panel.</summary>
    public static readonly (string Prefix, string Name)[] Unsupported =
    [
        ("AC", "accumulators (AC) belong to the running program; no link reads them"),
        ("HC", "high-speed counters (HC) have no area code over PPI in any source, and the Freeport handler does not reach them; no link reads them"),
        ("L", "local memory (L) belongs to the running program; no link reads it"),
    ];

    public static string Prefix(MemoryArea area) => area switch
    {
        MemoryArea.SM => "SM",
        MemoryArea.AI => "AI",
        MemoryArea.AQ => "AQ",
        MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.S or MemoryArea.T or MemoryArea.C or MemoryArea.AC or MemoryArea.HC or MemoryArea.L => area.ToString(),
    };

    /// <summary>
    /// Analog areas are words only; a timer or counter is its current value, one word (T37, C5); every other parsed
    /// area takes bits, bytes, words and double words.
    /// </summary>
    public static bool Allows(MemoryArea area, AccessWidth width) =>
        IsAnalog(area) || IsNumbered(area) ? width == AccessWidth.Word : IsByteAddressed(area);

    public static bool HasBits(MemoryArea area) => Allows(area, AccessWidth.Bit);

    public static bool IsAnalog(MemoryArea area) => area is MemoryArea.AI or MemoryArea.AQ;

    /// <summary>Timers and counters: addressed by their number, not by a byte (T37 is timer 37's current value).</summary>
    public static bool IsNumbered(MemoryArea area) => area is MemoryArea.T or MemoryArea.C;

    private static bool IsByteAddressed(MemoryArea area) =>
        area is MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.SM or MemoryArea.S or MemoryArea.L;
}
