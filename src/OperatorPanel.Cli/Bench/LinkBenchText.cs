using System.Globalization;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Bench;

/// <summary>Prints the link benchmark as text: the line, the assumptions, the plan, the figures, the targets, the measurement.</summary>
internal static class LinkBenchText
{
    public static void WriteModeled(TextWriter o, LinkBenchReport report)
    {
        ArgumentNullException.ThrowIfNull(o);
        ArgumentNullException.ThrowIfNull(report);
        var line = report.Line;
        o.WriteLine("opanel bench link: what one full refresh of a reference line costs on the wire");
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
        o.WriteLine("Assumptions");
        o.WriteLine("  character time = (1 start + 8 data + parity + 1 stop) / baud: 10 bits for 8N1, 11 bits for 8E1");
        o.WriteLine(Invariant($"  per exchange: PLC reply delay {report.Timing.ReplyDelayMs:0} ms + one PLC scan {report.Timing.ScanMs:0} ms = {report.Timing.PerExchangeMs:0} ms"));
        o.WriteLine("  refresh time = (PC->PLC + PLC->PC characters) x character time + exchanges x per-exchange time");
        o.WriteLine("  bytes each way = characters PC->PLC and PLC->PC, framing included");
        o.WriteLine("  one item per request = one READ per tag, per alarm bit and per I/Q byte (this protocol), or the seed");
        o.WriteLine("    paper's Table 1 commands with its binary frames (<MWxx?> 7 chars, reply <MWxx=zz> 9)");
        o.WriteLine("  READ LIST (steady state) = each frame of the plan stored once in the PLC with DEFINE LIST, then polled with");
        o.WriteLine("    a 12-character READ LIST; plain READ = the same frames sending their item descriptors every refresh");
        o.WriteLine("  the targets are evaluated on the steady-state refresh; the DEFINE LISTs are priced separately below");
        o.WriteLine("  lower bound = only the distinct data bytes (a bit costs its byte once): no request, no framing, no delays");
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
        WriteFigures(o, report);
        var define = report.DefineLists;
        var defineTimes = string.Join(", ", LineSetting.Modeled.Select(s => Invariant($"{define.RefreshMs(s, report.Timing):0.0} ms at {s}")));
        o.WriteLine($"  one-time cost, once per connection and after an invalidation: {define.Frames} DEFINE LIST exchange{(define.Frames == 1 ? string.Empty : "s")},");
        o.WriteLine($"    {define.RequestChars} characters PC->PLC + {define.ReplyChars} PLC->PC = {define.TotalChars}: {defineTimes}");
        o.WriteLine();
        o.WriteLine("Targets");
        foreach (var target in report.Targets)
        {
            o.WriteLine($"  {target.Verdict} {target.Name}: {target.Limit}");
            o.WriteLine($"       {target.Detail}");
        }
    }

    public static void WriteMeasured(TextWriter o, MeasuredRoundTrip measured)
    {
        ArgumentNullException.ThrowIfNull(o);
        ArgumentNullException.ThrowIfNull(measured);
        var s = measured.Exchanges;
        o.WriteLine();
        o.WriteLine($"Measured round trip over a socat pty to the simulated PLC ({measured.Settings}, {measured.Cycles} refreshes)");
        o.WriteLine(Invariant($"  per exchange:     min {Ms(s.RoundTripMin)}  avg {Ms(s.RoundTripAverage)}  max {Ms(s.RoundTripMax)}  ({s.Replies} replies, {s.Retries} retries, {s.Timeouts} timeouts, {s.CorruptFrames} corrupt)"));
        o.WriteLine(Invariant($"  per full refresh: min {measured.RefreshMinMs,7:0.00} ms  avg {measured.RefreshAverageMs,7:0.00} ms  max {measured.RefreshMaxMs,7:0.00} ms  ({measured.FramesPerRefresh} frames each, {measured.FramesFailed} failed)"));
        o.WriteLine("  note: a pty does not pace characters at the baud rate, so this is software turnaround plus the configured");
        o.WriteLine("  reply delay (and the link's inter-frame gap per refresh), not line time");
    }

    private static void WriteFigures(TextWriter o, LinkBenchReport report)
    {
        var settings = LineSetting.Modeled;
        o.WriteLine($"Per full refresh{string.Empty,-22} frames  PC->PLC  PLC->PC   total{string.Concat(settings.Select(s => $"{s,12}"))}");
        foreach (var row in report.Rows)
        {
            var times = string.Concat(settings.Select(s => Invariant($"{row.RefreshMs(s, report.Timing),9:0.0} ms")));
            o.WriteLine($"  {row.Name,-36} {row.Frames,6} {row.RequestChars,8} {row.ReplyChars,8} {row.TotalChars,7}{times}");
        }
    }

    private static string Describe(ReadItem item) =>
        item.Length == 1 ? $"{item.Area}B{item.Offset}" : $"{item.Area}B{item.Offset}-{item.Area}B{item.Offset + item.Length - 1}";

    private static string Ms(TimeSpan? value) => value is { } v ? Invariant($"{v.TotalMilliseconds,7:0.00} ms") : "      - ms";

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
