namespace OperatorPanel.Cli.Bench;

/// <summary>The `--json` shape of `opanel bench link`: the same figures as the text, as numbers.</summary>
internal static class LinkBenchJson
{
    public static object From(LinkBenchReport report, MeasuredRoundTrip? measured, string? measuredSkipped)
    {
        ArgumentNullException.ThrowIfNull(report);
        var line = report.Line;
        return new
        {
            line = new
            {
                cpu = $"{line.Cpu.Name} ({line.Cpu.Revision})",
                station = line.Station.Address,
                groups = line.Tags.GroupBy(t => t.Group).Select(g => new { group = g.Key, addresses = g.Select(t => t.Address.ToString()) }),
                items = line.Tags.Length,
                distinctDataBytes = line.DistinctDataBytes,
            },
            assumptions = new
            {
                bitsPerCharacter = LineSetting.Modeled.Select(s => new { baud = s.Baud, format = s.Format, bits = s.BitsPerCharacter, characterMs = s.CharacterMs }),
                replyDelayMs = report.Timing.ReplyDelayMs,
                scanMs = report.Timing.ScanMs,
            },
            plan = report.Plan.Frames.Select(f => f.Items.Select(i => new { area = i.Area.ToString(), offset = i.Offset, length = i.Length })),
            rows = report.Rows.Select(r => new
            {
                name = r.Name,
                frames = r.Frames,
                pcToPlcChars = r.RequestChars,
                plcToPcChars = r.ReplyChars,
                totalChars = r.TotalChars,
                refreshMs = LineSetting.Modeled.Select(s => new { setting = s.ToString(), ms = r.RefreshMs(s, report.Timing) }),
            }),
            defineListsOnce = new
            {
                note = "once per connection and after an invalidation; the targets use the steady-state refresh",
                exchanges = report.DefineLists.Frames,
                pcToPlcChars = report.DefineLists.RequestChars,
                plcToPcChars = report.DefineLists.ReplyChars,
                ms = LineSetting.Modeled.Select(s => new { setting = s.ToString(), ms = report.DefineLists.RefreshMs(s, report.Timing) }),
            },
            targets = report.Targets.Select(t => new { name = t.Name, verdict = t.Verdict, pass = t.Pass, ratio = t.Ratio, limit = t.Limit, detail = t.Detail }),
            measured = measured is null ? null : new
            {
                settings = measured.Settings,
                cycles = measured.Cycles,
                framesPerRefresh = measured.FramesPerRefresh,
                framesFailed = measured.FramesFailed,
                exchangeMinMs = measured.Exchanges.RoundTripMin?.TotalMilliseconds,
                exchangeAverageMs = measured.Exchanges.RoundTripAverage?.TotalMilliseconds,
                exchangeMaxMs = measured.Exchanges.RoundTripMax?.TotalMilliseconds,
                retries = measured.Exchanges.Retries,
                timeouts = measured.Exchanges.Timeouts,
                refreshMinMs = measured.RefreshMinMs,
                refreshAverageMs = measured.RefreshAverageMs,
                refreshMaxMs = measured.RefreshMaxMs,
                note = "a pty does not pace characters at the baud rate: software turnaround plus the configured reply delay, not line time",
            },
            measuredSkipped,
        };
    }
}
