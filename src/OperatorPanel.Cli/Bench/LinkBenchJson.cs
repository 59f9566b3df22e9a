namespace OperatorPanel.Cli.Bench;

/// <summary>The `--json` shape of `opanel bench link`: the same figures as the text, as numbers.</summary>
internal static class LinkBenchJson
{
    public static object From(LinkBenchReport report, MeasuredRoundTrip? measured, string? measuredSkipped)
    {
        ArgumentNullException.ThrowIfNull(report);
        var line = report.Line;
        var time = report.Time;
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
            plan = report.Plan.Frames.Select(f => f.Items.Select(i => new { area = i.Area.ToString(), offset = i.Offset, length = i.Length })),
            rows = report.Rows.Select(r => new
            {
                name = r.Name,
                frames = r.Frames,
                pcToPlcChars = r.RequestChars,
                plcToPcChars = r.ReplyChars,
                totalChars = r.TotalChars,
                lineMs = LineSetting.Modeled.Select(s => new { setting = s.ToString(), ms = r.LineMs(s) }),
            }),
            defineListsOnce = new
            {
                exchanges = report.DefineLists.Frames,
                pcToPlcChars = report.DefineLists.RequestChars,
                plcToPcChars = report.DefineLists.ReplyChars,
            },
            modelled = new
            {
                medium = time.Medium,
                setting = time.Model.Line.ToString(),
                replyDelayMs = time.Model.ReplyDelayMs,
                programScanMs = time.Model.ProgramScanMs,
                turnaroundMs = time.Model.TurnaroundMs,
                gapMs = time.Model.GapMs,
                radio = time.Model.Radio?.ToString(),
                handlerProblems = report.HandlerProblems,
                steady = Cycle(time.Steady),
                idle = Cycle(time.Idle),
                hexBoundChars = time.HexBoundChars,
                hexBoundMs = time.HexBoundMs,
                steadyRatio = time.SteadyRatio,
                summary = time.SummaryLine,
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

    private static object Cycle(CycleTime cycle) => new
    {
        chars = cycle.Chars,
        ms = cycle.TotalMs,
        exchanges = cycle.Exchanges.Select(e => new
        {
            name = e.Name,
            requestChars = e.RequestChars,
            replyChars = e.ReplyChars,
            ms = e.TotalMs,
            handlerScans = e.Handler.Scans,
            untilFirstReplyMs = e.Handler.UntilFirstReply.TotalMilliseconds,
            replyOnBusMs = e.Handler.ReplyOnBus.TotalMilliseconds,
            handlerSource = e.Handler.Source,
            parts = e.Parts.Select(p => new { what = p.What, ms = p.Ms }),
        }),
    };
}
