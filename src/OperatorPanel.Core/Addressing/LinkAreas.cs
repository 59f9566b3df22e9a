using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Addressing;

/// <summary>
/// What each link kind reaches, said one way everywhere (the CLI, project files, the wizard, the Memory pane, the poll
/// planners, <c>opanel address</c>).
/// <list type="bullet">
/// <item>Freeport talks to the handler we generate, which serves I, Q, M and V (docs/protocol.md section 1.3). The
/// handler reaches memory through pointers (&amp;IB0, &amp;VB0 ...); no S7-200 source found says a pointer reaches AI,
/// AQ or SM (docs/sources/s7200-facts.md section 13: the conservative side), and timers, counters and S bits, which a
/// pointer would reach, the handler leaves out to stay small. The program copies them to V for it (MOVW AIW0, VW100).</item>
/// <item>PPI talks to the CPU's own protocol, which has area codes for S, AI, AQ, T and C as well (docs/ppi.md section 6):
/// the panel reads them all over PPI; it writes S and AQ, never I (the field's), AI (inputs) or a timer's or counter's
/// current value (no source says how a CPU takes that write: the conservative side).</item>
/// </list>
/// </summary>
public static class LinkAreas
{
    /// <summary>The areas the Freeport link reads, as messages name them.</summary>
    public const string FreeportServed = "I, Q, M and V";

    /// <summary>
    /// The areas the Freeport link writes, as messages name them: the protocol 3 handler writes Q, M and V as its write
    /// mask allows and never I or SM (docs/protocol.md section 2, WRITE: 83).
    /// </summary>
    public const string FreeportWritten = "Q, M and V";

    /// <summary>The areas the PPI link reads, as messages name them.</summary>
    public const string PpiServed = "I, Q, M, V, SM, S, AIW, AQW, T and C";

    /// <summary>The areas the PPI link writes, as messages name them.</summary>
    public const string PpiWritten = "Q, M, V, SM, S and AQW";

    /// <summary>"I, Q, M and V" or the PPI list: what <paramref name="link"/> reads.</summary>
    public static string Served(LinkProtocol link) => link == LinkProtocol.Ppi ? PpiServed : FreeportServed;

    /// <summary>What <paramref name="link"/> writes, as messages name it.</summary>
    public static string Written(LinkProtocol link) => link == LinkProtocol.Ppi ? PpiWritten : FreeportWritten;

    /// <summary>True when <paramref name="link"/> reads the area (Freeport: area codes 01-04; PPI: docs/ppi.md section 6).</summary>
    public static bool Reads(LinkProtocol link, MemoryArea area) =>
        area is MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V
        || (link == LinkProtocol.Ppi && area is MemoryArea.SM or MemoryArea.S or MemoryArea.AI or MemoryArea.AQ or MemoryArea.T or MemoryArea.C);

    /// <summary>True when <paramref name="link"/> writes the area (the CPU's own read-only bytes aside: <see cref="AddressRules"/>).</summary>
    public static bool Writes(LinkProtocol link, MemoryArea area) =>
        area is MemoryArea.Q or MemoryArea.M or MemoryArea.V
        || (link == LinkProtocol.Ppi && area is MemoryArea.SM or MemoryArea.S or MemoryArea.AQ);

    /// <summary>Null when <paramref name="link"/> reads <paramref name="address"/>; otherwise why not and what to do instead.</summary>
    public static string? ReadRefusal(PlcAddress address, LinkProtocol link) =>
        Reads(link, address.Area) ? null : $"{address}: {NotServed(AreaSyntax.Prefix(address.Area), address.ToString(), link)}";

    /// <summary>
    /// Null when the panel may <paramref name="use"/> <paramref name="address"/> over <paramref name="link"/>: the link
    /// reaches it, and with a known <paramref name="cpu"/> the CPU has it (and lets it be written, for a write).
    /// </summary>
    public static string? Refusal(PlcAddress address, LinkProtocol link, CpuProfile? cpu, AddressUse use = AddressUse.Read)
    {
        if (ReadRefusal(address, link) is { } notRead)
        {
            // A write to SM over Freeport: the CPU's own rule first (SMB0-SMB29), then what to write instead (a V byte
            // the program copies), not what to watch.
            return use == AddressUse.Write && address.Area == MemoryArea.SM
                ? (cpu is null ? null : AddressRules.Check(address, cpu, use, link)?.Message) ?? WriteRefusal(address, link, "SM")
                : notRead;
        }

        if (cpu is not null)
        {
            return AddressRules.Check(address, cpu, use, link)?.Message;
        }

        return use == AddressUse.Write ? WriteRefusal(address, link, "SM") : null;
    }

    /// <summary>Null when <paramref name="link"/> writes the area; else the sentence (<paramref name="sm"/>: "SM" or "SMB30 and up").</summary>
    internal static string? WriteRefusal(PlcAddress address, LinkProtocol link, string sm) => address.Area switch
    {
        MemoryArea.I => $"{address}: inputs are read from the field; the panel never writes them",
        MemoryArea.AI => $"{address}: analog inputs are read-only",
        MemoryArea.T or MemoryArea.C =>
            $"{address}: the panel reads {(address.Area == MemoryArea.T ? "timer" : "counter")} current values but never writes them: no source says how a CPU takes that write over PPI, and the Freeport handler does not reach them",
        _ when Writes(link, address.Area) => null,
        MemoryArea.SM when link == LinkProtocol.Freeport =>
            $"{address}: the Freeport handler does not serve SM (no S7-200 manual page found says a pointer reaches it); "
            + "write a V byte and let the PLC program copy it, or reach the station over PPI (\"protocol\": \"ppi\"), which writes SM from SMB30 on",
        _ => $"{address}: the {Name(link)} link writes only {Written(link).Replace("SM", sm, StringComparison.Ordinal)}",
    };

    /// <summary>"the Freeport link reads only I, Q, M and V: ... copy ... to V ... or read the station over PPI".</summary>
    internal static string NotServed(string prefix, string example, LinkProtocol link = LinkProtocol.Freeport) => link == LinkProtocol.Ppi
        ? $"the PPI link reads only {PpiServed}: {Copy(prefix, example)} and watch that"
        : $"the Freeport link reads only {FreeportServed}: {Why(prefix)}; {Copy(prefix, example)} and watch that{OverPpi(prefix)}";

    private static string Name(LinkProtocol link) => link == LinkProtocol.Ppi ? "PPI" : "Freeport";

    /// <summary>Why the handler does not serve the area (docs/sources/s7200-facts.md section 13).</summary>
    private static string Why(string prefix) => prefix switch
    {
        "AI" or "AQ" => "its handler reaches memory through pointers, and an S7-200 pointer cannot reach analog values",
        "SM" => "its handler reaches memory through pointers, and no S7-200 manual page found says a pointer reaches SM",
        "T" or "C" or "S" => $"its handler leaves {What(prefix)} out to stay small",
        _ => "no link reaches this area",
    };

    private static string OverPpi(string prefix) => prefix is "AI" or "AQ" or "T" or "C" or "S" or "SM"
        ? $", or read the station over PPI (\"protocol\": \"ppi\"), which reads {What(prefix)}"
        : string.Empty;

    private static string Copy(string prefix, string example) => prefix switch
    {
        "AI" or "AQ" => $"copy the analog value to V in the PLC program (MOVW {example}, VW100)",
        "T" or "C" => $"copy the current value to V in the PLC program (MOVW {Unit(example, prefix)}, VW100)",
        "HC" => $"copy the counter to V in the PLC program (MOVD {Unit(example, prefix)}, VD100)",
        "S" => "copy the S bits to V in the PLC program (MOVB SB0, VB100)",
        "SM" => $"copy the SM bytes to V in the PLC program ({SmCopy(example)})",
        _ => "copy what you need to V in the PLC program",
    };

    private static string What(string prefix) => prefix switch
    {
        "AI" or "AQ" => "analog values",
        "T" => "timers",
        "C" => "counters",
        "S" => "S bits",
        "SM" => "SM",
        _ => "more areas",
    };

    /// <summary>The copy of an SM example at its width: SMW22 -> MOVW SMW22, VW100; SM0.5 -> MOVB SMB0, VB100; else SMB28.</summary>
    private static string SmCopy(string example)
    {
        var upper = example.ToUpperInvariant();
        var width = upper.StartsWith("SMW", StringComparison.Ordinal) ? 'W' : upper.StartsWith("SMD", StringComparison.Ordinal) ? 'D' : 'B';
        var digits = new string([.. upper.SkipWhile(c => !char.IsAsciiDigit(c)).TakeWhile(char.IsAsciiDigit)]);
        var at = digits.Length is > 0 and <= 4 ? digits : "28";
        return $"MOV{width} SM{width}{at}, V{width}100";
    }

    /// <summary>A timer or counter example of the area: T37 as typed, else T37.</summary>
    private static string Unit(string example, string prefix) =>
        example.StartsWith(prefix, StringComparison.OrdinalIgnoreCase) && example.Length > prefix.Length && example.Length <= 8
            && example[prefix.Length..].All(char.IsAsciiDigit)
            ? example.ToUpperInvariant()
            : prefix + (prefix == "T" ? "37" : "0");
}
