using OperatorPanel.Core.Messages;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Commands;

/// <summary>A project as opanel summarises it after <c>project new</c> and a clean <c>project check</c> (text and JSON).</summary>
internal sealed record ProjectSummaryView(string Name, string Refresh, int MinimumPeriodMs, IReadOnlyList<StationSummaryView> Stations)
{
    public static ProjectSummaryView From(PanelProject project) => new(
        project.Name,
        project.Refresh.Mode == RefreshMode.Continuous ? "continuous" : "triggered",
        (int)project.Refresh.MinimumPeriod.TotalMilliseconds,
        project.Stations.Select(StationSummaryView.From).ToList());

    /// <summary>
    /// Names and ports pass through <see cref="QuotedText.OneLine"/>: a project that loaded has none with control
    /// characters (TextRule), so this only guards the terminal should one ever reach here another way.
    /// </summary>
    public void WriteText(TextWriter o)
    {
        var refresh = Refresh == "continuous" ? $"continuous refresh, at least {MinimumPeriodMs} ms apart" : "triggered refresh";
        o.WriteLine($"project   \"{QuotedText.OneLine(Name)}\", {Count(Stations.Count, "station")}, {refresh}");
        foreach (var s in Stations)
        {
            o.WriteLine($"station   {s.Address} \"{QuotedText.OneLine(s.Name)}\": {s.Cpu} on {QuotedText.OneLine(s.Port)} {s.Line}{(s.Handler == "none" ? "" : $", {s.Handler} handler")}; "
                + $"{Count(s.Inputs, "input")}, {Count(s.Outputs, "output")}, {Count(s.Tags, "tag")}, {Count(s.Alarms, "alarm")}");
        }
    }

    private static string Count(int n, string noun) => n == 1 ? $"1 {noun}" : $"{n} {noun}s";
}

/// <summary>One station of the summary; <see cref="Handler"/> is the handler <c>opanel generate</c> writes for it: "full", "compact" or "none" (PPI).</summary>
internal sealed record StationSummaryView(string Name, int Address, string Cpu, string Port, string Line, string Handler, int Inputs, int Outputs, int Tags, int Alarms)
{
    public static StationSummaryView From(ProjectStation s) => new(
        s.Name,
        s.Address.Address,
        s.Cpu.DisplayName,
        s.Link.PortName,
        Describe(s.Link),
        s.Link.Protocol == LinkProtocol.Ppi ? "none" : s.Compact ? "compact" : "full",
        s.Inputs.Length,
        s.Outputs.Length,
        s.Tags.Length,
        s.Alarms.Length);

    /// <summary>"9600 8N1 cable", as technicians write line settings.</summary>
    private static string Describe(SerialSettings link) =>
        $"{link.LineText} {(link.Kind == LinkKind.Cable ? "cable" : "radio module")}{(link.Protocol == LinkProtocol.Ppi ? ", PPI (no handler)" : "")}";

}
