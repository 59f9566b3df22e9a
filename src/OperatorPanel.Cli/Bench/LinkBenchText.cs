using System.Globalization;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// Prints the link benchmark as text: the line, the plan, the characters per strategy, the time model (labelled
/// modelled) with its sources, the targets; the measurement (labelled measured) is printed by <see cref="WriteMeasured"/>.
/// </summary>
internal static class LinkBenchText
{
    public static void WriteModeled(TextWriter o, LinkBenchReport report)
    {
        ArgumentNullException.ThrowIfNull(o);
        ArgumentNullException.ThrowIfNull(report);
        var line = report.Line;
        o.WriteLine("opanel bench link: what a refresh of a reference line costs on the wire (MODELLED unless marked measured)");
        o.WriteLine();
        o.WriteLine($"Reference line: {line.Cpu.Name} ({line.Cpu.Revision}), station {line.Station.Address}");
        foreach (var group in line.Tags.GroupBy(t => t.Group))
        {
            var addresses = group.Select(t => t.Address.ToString()).ToList();
            var shown = group.Key == "alarms" ? $"{addresses[0]}-{addresses[^1]}" : string.Join(' ', addresses);
            o.WriteLine($"  {group.Key,-10} {addresses.Count,3}  {shown}");
        }

        o.WriteLine($"  watched {line.Tags.Length} items holding {line.DistinctDataBytes} distinct data bytes");
        o.WriteLine();
        o.WriteLine($"Poll plan (PollPlanner, CPU known): {report.Plan.FrameCount} READ frames, {report.Plan.DataBytes} data bytes with bridged gaps");
        var lists = ReadListAssignment.For(report.Plan);
        for (var i = 0; i < report.Plan.Frames.Length; i++)
        {
            var frame = report.Plan.Frames[i];
            var how = lists.TryGetValue(i, out var list) ? $"list {list}" : "plain READ";
            o.WriteLine($"  frame {i + 1} ({how}, {frame.Items.Length} items, {frame.DataBytes} bytes): {string.Join(", ", frame.Items.Select(Describe))}");
        }

        o.WriteLine();
        WriteCharacters(o, report);
        o.WriteLine();
        LinkTimeText.Write(o, report.Time, report.HandlerProblems);
        o.WriteLine();
        o.WriteLine("Goals for the reference line (a goal not met is a finding to read, not an error of the benchmark)");
        foreach (var target in report.Targets)
        {
            o.WriteLine($"  {target.Verdict,-7} {target.Name}: {target.Limit}");
            o.WriteLine($"          {target.Detail}");
        }
    }

    public static void WriteMeasured(TextWriter o, MeasuredRoundTrip measured)
    {
        ArgumentNullException.ThrowIfNull(o);
        ArgumentNullException.ThrowIfNull(measured);
        var s = measured.Exchanges;
        o.WriteLine();
        o.WriteLine($"MEASURED round trip over a socat pty to the simulated PLC ({measured.Settings}, {measured.Cycles} refreshes)");
        o.WriteLine(Invariant($"  per exchange:     min {Ms(s.RoundTripMin)}  avg {Ms(s.RoundTripAverage)}  max {Ms(s.RoundTripMax)}  ({s.Replies} replies, {s.Retries} retries, {s.Timeouts} timeouts, {s.CorruptFrames} corrupt)"));
        o.WriteLine(Invariant($"  per full refresh: min {measured.RefreshMinMs,7:0.00} ms  avg {measured.RefreshAverageMs,7:0.00} ms  max {measured.RefreshMaxMs,7:0.00} ms  ({measured.FramesPerRefresh} frames each, {measured.FramesFailed} failed)"));
        o.WriteLine("  note: a pty does not pace characters at the baud rate and the reference model answers at once, so this is");
        o.WriteLine("  the PC software's turnaround plus the configured reply delay and the link's gap, not line or PLC time");
    }

    private static void WriteCharacters(TextWriter o, LinkBenchReport report)
    {
        var settings = LineSetting.Modeled;
        o.WriteLine("Characters per full refresh, and their line time alone (no handler, delay or gap; the time model below has those)");
        o.WriteLine($"  {"strategy",-36} frames  PC->PLC  PLC->PC   total{string.Concat(settings.Select(s => $"{s,12}"))}");
        foreach (var row in report.Rows)
        {
            var times = string.Concat(settings.Select(s => Invariant($"{row.LineMs(s),9:0.0} ms")));
            o.WriteLine($"  {row.Name,-36} {row.Frames,6} {row.RequestChars,8} {row.ReplyChars,8} {row.TotalChars,7}{times}");
        }

        var define = report.DefineLists;
        o.WriteLine($"  one-time cost, once per connection and after an invalidation: {define.Frames} exchange{(define.Frames == 1 ? string.Empty : "s")} (DEFINE LIST, first READ CHANGES),");
        o.WriteLine($"    {define.RequestChars} characters PC->PLC + {define.ReplyChars} PLC->PC = {define.TotalChars}");
    }

    private static string Describe(ReadItem item) =>
        item.Length == 1 ? $"{item.Area}B{item.Offset}" : $"{item.Area}B{item.Offset}-{item.Area}B{item.Offset + item.Length - 1}";

    private static string Ms(TimeSpan? value) => value is { } v ? Invariant($"{v.TotalMilliseconds,7:0.00} ms") : "      - ms";

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
