using System.Globalization;
using OperatorPanel.Core.Messages;

namespace OperatorPanel.Cli.Watch;

/// <summary>
/// The lines of a <see cref="WatchSnapshot"/>: per station a header with link state and counters, inputs and outputs as
/// lamps grouped by byte with their symbols beside, the tags as a table, and the alarms; each line with its
/// <see cref="ViewLine.Priority"/>, so a low terminal gives way in that order (<see cref="WatchScreen"/>).
/// </summary>
internal static class SnapshotRenderer
{
    /// <summary>Symbols listed beside a lamp row before wrapping to the next line.</summary>
    private const int SymbolsPerLine = 4;

    /// <summary>The whole view as text, as pipes, files and --once get it (nothing cut).</summary>
    public static string Render(WatchSnapshot snapshot) =>
        string.Concat(Lines(snapshot).Select(l => l.Text + Environment.NewLine));

    public static List<ViewLine> Lines(WatchSnapshot snapshot)
    {
        var o = new LineList();
        var time = snapshot.Time.ToString("HH:mm:ss", CultureInfo.InvariantCulture);
        o.Add(ViewLine.Keep, $"{snapshot.Project}  ({snapshot.Refresh})  cycle {snapshot.Cycle}  {time}", ViewLineKind.Title);
        foreach (var station in snapshot.Stations)
        {
            o.Add(ViewLine.Spacing, string.Empty);
            Station(o, station);
        }

        return o.Items;
    }

    private static void Station(LineList o, StationSnapshot s)
    {
        var l = s.Link;
        var rtt = l.RoundTripAverageMs is { } ms ? ms.ToString("0.0", CultureInfo.InvariantCulture) + " ms" : "-";
        var resting = s.NextTryInSeconds is { } n ? $" (next try in {n} s: others on the bus answer)" : string.Empty;
        o.Add(ViewLine.Keep, $"{s.Name}  station {s.Station}  {s.Cpu}  {s.Port}  {s.State}{resting}", ViewLineKind.Station);
        o.Add(ViewLine.Link, $"  link     requests {l.Requests}  replies {l.Replies}  retries {l.Retries}  timeouts {l.Timeouts}  rtt avg {rtt}");
        if (s.Handler is not null)
        {
            o.Add(ViewLine.Link, $"  handler  {s.Handler}", s.Handler.StartsWith("ok", StringComparison.Ordinal) ? ViewLineKind.Plain : ViewLineKind.Problem);
        }

        if (s.LastError is not null)
        {
            // Kept after the station answers again (the cause stays readable); then it is history, not the present state.
            var label = s.State == "online" ? "earlier error (it answers now)" : "last error";
            o.Add(s.State == "online" ? ViewLine.Link : ViewLine.Keep, $"  {label}: {s.LastError}", s.State == "online" ? ViewLineKind.Plain : ViewLineKind.Problem);
        }

        Lamps(o, "inputs", s.Inputs);
        Lamps(o, "outputs", s.Outputs);
        Tags(o, s.Tags);
        Alarms(o, s);
    }

    /// <summary>
    /// "none active" only when every flag of the station was read; otherwise "unknown: Filler offline (8 of 8 flags not
    /// read)", so a dead link never reads as all clear. Active alarms are listed; the unknown ones are counted (JSON
    /// lists them), so an offline station does not push the rest of the view off the screen.
    /// </summary>
    private static void Alarms(LineList o, StationSnapshot s)
    {
        var unknown = s.AlarmsUnknown;
        var active = s.AlarmsActive;
        if (unknown > 0)
        {
            var why = s.State == "online" ? "flags not read yet" : s.State;
            var known = active > 0 ? $"; {active} active" : string.Empty;
            o.Add(ViewLine.Keep, $"  alarms   unknown: {s.Name} {why} ({unknown} of {s.AlarmsDefined} flags not read){known}", ViewLineKind.Unknown);
        }
        else
        {
            o.Add(ViewLine.Keep, active == 0 ? "  alarms   none active" : $"  alarms   {active} active", active == 0 ? ViewLineKind.Plain : ViewLineKind.Alarm);
        }

        var shown = s.Alarms.Where(a => a.State == AlarmRow.Active).ToList();
        if (shown.Count == 0)
        {
            return;
        }

        var classWidth = shown.Max(a => a.Class.Length);
        foreach (var alarm in shown)
        {
            o.Add(ViewLine.Keep, $"    {alarm.Flag,-6} {alarm.Class.PadRight(classWidth)}  {alarm.Text}", ViewLineKind.Alarm);
        }
    }

    private static void Lamps(LineList o, string title, IReadOnlyList<LampByte> bytes)
    {
        if (bytes.Count == 0)
        {
            return;
        }

        o.Add(ViewLine.Lamps, $"  {title} (bit 0 first; {LampByte.On} on, {LampByte.Off} off, {LampByte.Unknown} unknown: not read, stale or bad)");
        foreach (var b in bytes)
        {
            var prefix = $"    {b.Byte,-5} {b.Lamps}  ";
            for (var i = 0; i < b.Bits.Count; i += SymbolsPerLine)
            {
                var symbols = string.Join("  ", b.Bits.Skip(i).Take(SymbolsPerLine).Select(bit => $"{bit.Address} {bit.Symbol}"));
                o.Add(i == 0 ? ViewLine.Lamps : ViewLine.LampSymbols, (i == 0 ? prefix : new string(' ', prefix.Length)) + symbols);
            }
        }
    }

    private static void Tags(LineList o, IReadOnlyList<TagRow> tags)
    {
        if (tags.Count == 0)
        {
            return;
        }

        var symbol = Math.Max("symbol".Length, tags.Max(t => t.Symbol.Length));
        var address = Math.Max("address".Length, tags.Max(t => t.Address.Length));
        var value = Math.Max("value".Length, tags.Max(t => t.Value.Length));
        o.Add(ViewLine.Tags, "  tags");
        o.Add(ViewLine.Tags, $"    {"symbol".PadRight(symbol)}  {"address".PadRight(address)}  {"value".PadLeft(value)}  quality");
        foreach (var t in tags)
        {
            o.Add(ViewLine.Tags, $"    {t.Symbol.PadRight(symbol)}  {t.Address.PadRight(address)}  {t.Value.PadLeft(value)}  {t.Quality}");
        }
    }

    /// <summary>
    /// The lines being built. Each passes through <see cref="QuotedText.OneLine"/>: a loaded project's names and texts have
    /// no control characters (TextRule), but a line also carries errors and values, and one ESC in a live view redrawn
    /// in place would move the cursor or clear the screen.
    /// </summary>
    private sealed class LineList
    {
        public List<ViewLine> Items { get; } = [];

        public void Add(int priority, string text, ViewLineKind kind = ViewLineKind.Plain) => Items.Add(new ViewLine(QuotedText.OneLine(text), priority, kind));
    }
}
