namespace OperatorPanel.Core.Addressing;

/// <summary>
/// What each link kind reaches, said one way everywhere (the CLI, project files, the wizard, <c>opanel address</c>).
/// The Freeport link talks to the handler we generate, whose protocol has area codes for I, Q, M, V and SM only
/// (docs/protocol.md, "Area codes"): analog values, timers, counters and S bits are out of its reach, and the PLC program
/// can copy them to V for it (MOVW AIW0, VW100). The PPI link talks to the CPU's own protocol, which needs no handler and
/// has those areas too (docs/ppi.md section 6), but the panel watches I, Q, M, V and SM over PPI as well so far: every
/// message names the copy as the way.
/// </summary>
public static class LinkAreas
{
    /// <summary>The areas the Freeport link reads, as messages name them.</summary>
    public const string FreeportServed = "I, Q, M, V and SM";

    /// <summary>The areas the Freeport link writes (the handler's WRITE_MASK never has I), as messages name them.</summary>
    public const string FreeportWritten = "Q, M, V and SM";

    /// <summary>True when the Freeport handler serves the area (area codes 01-05).</summary>
    public static bool FreeportServes(MemoryArea area) =>
        area is MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.SM;

    /// <summary>Null when the Freeport link reads <paramref name="address"/>; otherwise why not and what to do instead.</summary>
    public static string? FreeportRefusal(PlcAddress address) =>
        FreeportServes(address.Area) ? null : $"{address}: {NotServed(AreaSyntax.Prefix(address.Area), address.ToString())}";

    /// <summary>"the Freeport link reads only I, Q, M, V and SM: copy ... to V in the PLC program (...) and watch that".</summary>
    internal static string NotServed(string prefix, string example) =>
        $"the Freeport link reads only {FreeportServed}: {Copy(prefix, example)} and watch that; the CPU's own PPI protocol has {What(prefix)} too, but the panel's PPI link does not read them yet";

    private static string Copy(string prefix, string example) => prefix switch
    {
        "AI" or "AQ" => $"copy the analog value to V in the PLC program (MOVW {example}, VW100)",
        "T" or "C" => $"copy the current value to V in the PLC program (MOVW {Unit(example, prefix)}, VW100)",
        "HC" => $"copy the counter to V in the PLC program (MOVD {Unit(example, prefix)}, VD100)",
        "S" => "copy the S bits to V in the PLC program (MOVB SB0, VB100)",
        _ => "copy what you need to V in the PLC program",
    };

    private static string What(string prefix) => prefix switch
    {
        "AI" or "AQ" => "analog values",
        "T" => "timers",
        "C" => "counters",
        "S" => "S bits",
        _ => "more areas",
    };

    /// <summary>A timer or counter example of the area: T37 as typed, else T37.</summary>
    private static string Unit(string example, string prefix) =>
        example.StartsWith(prefix, StringComparison.OrdinalIgnoreCase) && example.Length > prefix.Length && example.Length <= 8
            && example[prefix.Length..].All(char.IsAsciiDigit)
            ? example.ToUpperInvariant()
            : prefix + (prefix == "T" ? "37" : "0");
}
