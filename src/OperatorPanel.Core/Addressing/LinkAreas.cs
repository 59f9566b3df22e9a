using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Addressing;

/// <summary>
/// What each link kind reaches, said one way everywhere (the CLI, project files, the wizard, the Memory pane, the poll
/// planners, <c>opanel address</c>).
/// <list type="bullet">
/// <item>Freeport talks to the handler we generate, whose protocol has area codes for I, Q, M, V and SM only
/// (docs/protocol-v2.md, "Area codes"). The handler reaches memory through pointers (&amp;IB0, &amp;SMB0 ...); an S7-200
/// pointer does not reach AI and AQ (docs/sources/s7200-facts.md section 13), and timers, counters and S bits, which a
/// pointer would reach, the handler leaves out to stay small. The program copies them to V for it (MOVW AIW0, VW100).</item>
/// <item>PPI talks to the CPU's own protocol, which has area codes for S, AI, AQ, T and C as well (docs/ppi.md section 6):
/// the panel reads them all over PPI; it writes S and AQ, never I (the field's), AI (inputs) or a timer's or counter's
/// current value (no source says how a CPU takes that write: the conservative side).</item>
/// </list>
/// </summary>
public static class LinkAreas
{
    /// <summary>The areas the Freeport link reads, as messages name them.</summary>
    public const string FreeportServed = "I, Q, M, V and SM";

    /// <summary>
    /// The areas the Freeport link writes, as messages name them: the protocol 3 handler writes Q, M and V as its write
    /// mask allows and never I or SM (docs/protocol.md section 2, WRITE: 83).
    /// </summary>
    public const string FreeportWritten = "Q, M and V";

    /// <summary>The areas the PPI link reads, as messages name them.</summary>
    public const string PpiServed = "I, Q, M, V, SM, S, AIW, AQW, T and C";

    /// <summary>The areas the PPI link writes, as messages name them.</summary>
    public const string PpiWritten = "Q, M, V, SM, S and AQW";

    /// <summary>"I, Q, M, V and SM" or the PPI list: what <paramref name="link"/> reads.</summary>
    public static string Served(LinkProtocol link) => link == LinkProtocol.Ppi ? PpiServed : FreeportServed;

    /// <summary>What <paramref name="link"/> writes, as messages name it.</summary>
    public static string Written(LinkProtocol link) => link == LinkProtocol.Ppi ? PpiWritten : FreeportWritten;

    /// <summary>True when <paramref name="link"/> reads the area (Freeport: area codes 01-05; PPI: docs/ppi.md section 6).</summary>
    public static bool Reads(LinkProtocol link, MemoryArea area) =>
        area is MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.SM
        || (link == LinkProtocol.Ppi && area is MemoryArea.S or MemoryArea.AI or MemoryArea.AQ or MemoryArea.T or MemoryArea.C);

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
            return notRead;
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
            $"{address}: the Freeport handler never writes SM (it refuses with 83: the CPU's system bytes and the port's receive set-up are there); "
            + "write a V byte and let the PLC program copy it, or reach the station over PPI (\"protocol\": \"ppi\")",
        _ => $"{address}: the {Name(link)} link writes only {Written(link).Replace("SM", sm, StringComparison.Ordinal)}",
    };

    /// <summary>"the Freeport link reads only I, Q, M, V and SM: ... copy ... to V ... or read the station over PPI".</summary>
    internal static string NotServed(string prefix, string example, LinkProtocol link = LinkProtocol.Freeport) => link == LinkProtocol.Ppi
        ? $"the PPI link reads only {PpiServed}: {Copy(prefix, example)} and watch that"
        : $"the Freeport link reads only {FreeportServed}: {Why(prefix)}; {Copy(prefix, example)} and watch that{OverPpi(prefix)}";

    private static string Name(LinkProtocol link) => link == LinkProtocol.Ppi ? "PPI" : "Freeport";

    /// <summary>Why the handler does not serve the area (docs/sources/s7200-facts.md section 13).</summary>
    private static string Why(string prefix) => prefix switch
    {
        "AI" or "AQ" => "its handler reaches memory through pointers, and an S7-200 pointer cannot reach analog values",
        "T" or "C" or "S" => $"its handler leaves {What(prefix)} out to stay small",
        _ => "no link reaches this area",
    };

    private static string OverPpi(string prefix) => prefix is "AI" or "AQ" or "T" or "C" or "S"
        ? $", or read the station over PPI (\"protocol\": \"ppi\"), which reads {What(prefix)}"
        : string.Empty;

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
