using System.Globalization;
using System.Text;

namespace OperatorPanel.Cli.Watch;

/// <summary>
/// The text of a <see cref="WatchSnapshot"/>: per station a header with link state and counters, inputs and outputs as
/// lamps grouped by byte with their symbols beside, the tags as a table, and the active alarms.
/// </summary>
internal static class SnapshotRenderer
{
    /// <summary>Symbols listed beside a lamp row before wrapping to the next line.</summary>
    private const int SymbolsPerLine = 4;

    public static string Render(WatchSnapshot snapshot)
    {
        var o = new StringBuilder();
        var time = snapshot.Time.ToString("HH:mm:ss", CultureInfo.InvariantCulture);
        o.AppendLine(CultureInfo.InvariantCulture, $"{snapshot.Project}  ({snapshot.Refresh})  cycle {snapshot.Cycle}  {time}");
        foreach (var station in snapshot.Stations)
        {
            o.AppendLine();
            Station(o, station);
        }

        return o.ToString();
    }

    private static void Station(StringBuilder o, StationSnapshot s)
    {
        var l = s.Link;
        var rtt = l.RoundTripAverageMs is { } ms ? ms.ToString("0.0", CultureInfo.InvariantCulture) + " ms" : "-";
        var resting = s.NextTryInSeconds is { } n ? $" (next try in {n} s: others on the bus answer)" : string.Empty;
        o.AppendLine(CultureInfo.InvariantCulture, $"{s.Name}  station {s.Station}  {s.Cpu}  {s.Port}  {s.State}{resting}");
        o.AppendLine(CultureInfo.InvariantCulture, $"  link     requests {l.Requests}  replies {l.Replies}  retries {l.Retries}  timeouts {l.Timeouts}  rtt avg {rtt}");
        if (s.Handler is not null)
        {
            o.AppendLine(CultureInfo.InvariantCulture, $"  handler  {s.Handler}");
        }

        if (s.LastError is not null)
        {
            // Kept after the station answers again (the cause stays readable); then it is history, not the present state.
            var label = s.State == "online" ? "earlier error (it answers now)" : "last error";
            o.AppendLine(CultureInfo.InvariantCulture, $"  {label}: {s.LastError}");
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
    private static void Alarms(StringBuilder o, StationSnapshot s)
    {
        var unknown = s.AlarmsUnknown;
        var active = s.AlarmsActive;
        if (unknown > 0)
        {
            var why = s.State == "online" ? "flags not read yet" : s.State;
            var known = active > 0 ? $"; {active} active" : string.Empty;
            o.AppendLine(CultureInfo.InvariantCulture, $"  alarms   unknown: {s.Name} {why} ({unknown} of {s.AlarmsDefined} flags not read){known}");
        }
        else
        {
            o.AppendLine(active == 0 ? "  alarms   none active" : string.Create(CultureInfo.InvariantCulture, $"  alarms   {active} active"));
        }

        var shown = s.Alarms.Where(a => a.State == AlarmRow.Active).ToList();
        if (shown.Count == 0)
        {
            return;
        }

        var classWidth = shown.Max(a => a.Class.Length);
        foreach (var alarm in shown)
        {
            o.AppendLine(CultureInfo.InvariantCulture, $"    {alarm.Flag,-6} {alarm.Class.PadRight(classWidth)}  {alarm.Text}");
        }
    }

    private static void Lamps(StringBuilder o, string title, IReadOnlyList<LampByte> bytes)
    {
        if (bytes.Count == 0)
        {
            return;
        }

        o.AppendLine(CultureInfo.InvariantCulture, $"  {title} (bit 0 first; {LampByte.On} on, {LampByte.Off} off, {LampByte.Unknown} not read)");
        foreach (var b in bytes)
        {
            var prefix = $"    {b.Byte,-5} {b.Lamps}  ";
            for (var i = 0; i < b.Bits.Count; i += SymbolsPerLine)
            {
                var symbols = string.Join("  ", b.Bits.Skip(i).Take(SymbolsPerLine).Select(bit => $"{bit.Address} {bit.Symbol}"));
                o.Append(i == 0 ? prefix : new string(' ', prefix.Length)).AppendLine(symbols);
            }
        }
    }

    private static void Tags(StringBuilder o, IReadOnlyList<TagRow> tags)
    {
        if (tags.Count == 0)
        {
            return;
        }

        var symbol = Math.Max("symbol".Length, tags.Max(t => t.Symbol.Length));
        var address = Math.Max("address".Length, tags.Max(t => t.Address.Length));
        var value = Math.Max("value".Length, tags.Max(t => t.Value.Length));
        o.AppendLine("  tags");
        o.AppendLine(CultureInfo.InvariantCulture, $"    {"symbol".PadRight(symbol)}  {"address".PadRight(address)}  {"value".PadLeft(value)}  quality");
        foreach (var t in tags)
        {
            o.AppendLine(CultureInfo.InvariantCulture, $"    {t.Symbol.PadRight(symbol)}  {t.Address.PadRight(address)}  {t.Value.PadLeft(value)}  {t.Quality}");
        }
    }
}
