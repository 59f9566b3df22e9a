using System.CommandLine;
using System.Globalization;
using OperatorPanel.Cli.Bench.History;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel bench history [--tags 2000] [--hours 1] [--project P]</c>: what the historian costs, recording on simulated
/// time as fast as the machine goes: the demo line (the sample project's values every 100 ms) and N analogue tags
/// changing every second, each for --hours of line time with the project's default history settings; CPU as a share of
/// one core while the line runs in real time, rows, database size and growth per day; then the writer's insert rate.
/// Goals (issue 22): 2000 tags changing every second under 5 % of one core and under 100 MB a day.
/// </summary>
internal static class HistoryBenchCommand
{
    public const double CoreGoalPercent = 5;
    public const double DayGoalMb = 100;

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var tags = new Option<int>("--tags") { Description = "Analogue tags changing every second (default 2000)", DefaultValueFactory = _ => 2000 };
        var hours = new Option<double>("--hours") { Description = "Hours of line time recorded per stream (default 1)", DefaultValueFactory = _ => 1 };
        var project = new Option<string?>("--project") { Description = "The demo line's project (default the sample bottling line)" };
        var command = new Command("history", "Recording cost of the historian: CPU, rows, database growth per day, insert rate (simulated time)") { tags, hours, project };
        command.SetAction(async parse =>
        {
            var cli = context(parse);
            var (count, span) = (parse.GetValue(tags), parse.GetValue(hours));
            if (count is < 1 or > 5000 || !(span > 0 && span <= 48))
            {
                return cli.Fail(ExitCodes.BadInput, "--tags 1-5000 (one CPU 226's V memory), --hours above 0 and up to 48");
            }

            var path = parse.GetValue(project) ?? Path.Combine(AppContext.BaseDirectory, "samples", "bottling-line.opproj");
            var load = ProjectFile.Load(path);
            if (!load.Ok)
            {
                return ProjectProblemsView.Report(cli, path, load, "no bench run");
            }

            var folder = Path.Combine(Path.GetTempPath(), "opanel-bench-history-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(folder);
            try
            {
                var duration = TimeSpan.FromHours(span);
                var demo = await HistoryBench.RunAsync(() => new DemoLineStream(load.Project), duration, folder);
                var many = await HistoryBench.RunAsync(() => new SyntheticTagStream(count, HistorySettings.Default), duration, folder);
                var rate = await HistoryBench.InsertRateAsync(200_000, 10_000, folder);
                Print(cli, demo, many, rate);
                return ExitCodes.Ok;
            }
            finally
            {
                Directory.Delete(folder, recursive: true);
            }
        });
        return command;
    }

    private static void Print(CliContext cli, HistoryBenchResult demo, HistoryBenchResult many, double rate)
    {
        var core = many.CorePercent < CoreGoalPercent ? "met" : "NOT MET";
        var day = many.MbPerDay < DayGoalMb ? "met" : "NOT MET";
        if (cli.Json)
        {
            cli.WriteJson(new
            {
                settings = HistorySettings.Default.ToString(),
                streams = new[] { demo, many }.Select(r => new
                {
                    stream = r.Stream,
                    values = r.Values,
                    lineHours = r.LineTime.TotalHours,
                    wallSeconds = r.Wall.TotalSeconds,
                    rows = r.Rows,
                    samples = r.Samples,
                    databaseBytes = r.Bytes,
                    bytesPerRow = r.BytesPerRow,
                    mbPerDay = r.MbPerDay,
                    corePercent = r.CorePercent,
                    cpuMicrosecondsPerRow = r.CpuMicrosecondsPerRow,
                }),
                insertRowsPerSecond = rate,
                goals = new { corePercent = core, mbPerDay = day },
            });
            return;
        }

        cli.Out.WriteLine($"history bench: simulated line time, default settings ({HistorySettings.Default})");
        cli.Out.WriteLine(demo.Line());
        cli.Out.WriteLine(many.Line());
        cli.Out.WriteLine(string.Create(CultureInfo.InvariantCulture, $"insert rate (writer alone, batches of 10000 rows): {rate:0} rows/s"));
        cli.Out.WriteLine(string.Create(
            CultureInfo.InvariantCulture,
            $"goals for {many.Stream}: cpu {many.CorePercent:0.00} % < {CoreGoalPercent} % of a core {core}; growth {many.MbPerDay:0.0} MB/day < {DayGoalMb} MB {day}"));
    }
}
