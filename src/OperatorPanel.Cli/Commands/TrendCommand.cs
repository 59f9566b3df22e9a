using System.CommandLine;
using OperatorPanel.Cli.History;
using OperatorPanel.Cli.Hosting;
using OperatorPanel.Cli.Link;
using OperatorPanel.Cli.Trend;
using OperatorPanel.Cli.Watch;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Storage;
using Spectre.Console;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel trend TAG... --project P [--demo] [--span 10m] [--duration S]</c>: the project's line opened as
/// <c>watch</c> opens it (recording into its history), and a live chart per tag drawn in the terminal from the history of
/// the last <c>--span</c>, redrawn every second.
/// </summary>
internal static class TrendCommand
{
    private static readonly TimeSpan RedrawPeriod = TimeSpan.FromSeconds(1);

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var tags = new Argument<string[]>("tag") { Description = "Symbols (TankLevel, Filler.TankLevel) or addresses (VW150)", Arity = ArgumentArity.OneOrMore };
        var project = new Option<string>("--project") { Description = "The .opproj project file", Required = true };
        var demo = new Option<bool>("--demo") { Description = "Simulate every station in-process (the demo process) instead of opening the ports" };
        var model = ModelOption.Create();
        var span = new Option<string>("--span") { Description = "The window the chart shows, back from now: 90s, 10m, 2h (default 10m)", DefaultValueFactory = _ => "10m" };
        var duration = new Option<double?>("--duration") { HelpName = "seconds", Description = "Stop after this many seconds (default: until Ctrl+C)" };
        var width = new Option<int>("--width") { Description = "Chart columns (default 72)", DefaultValueFactory = _ => 72 };
        var height = new Option<int>("--height") { Description = "Chart rows per tag (default 6)", DefaultValueFactory = _ => 6 };
        var command = new Command(
            "trend",
            "Draw a live chart of tags in the terminal, from the project's history over the last --span (the line is opened and recorded as watch does). "
            + "Redraws in place on a terminal; elsewhere prints the last chart at the end; --json prints one line a second with each tag's value. "
            + "A '·' marks a gap: not recorded, stale or bad; a station not online is named with its last error above the charts. "
            + "Exit codes: 0 done, 1 bad input or project problems, 2 every station offline at the end, or the history could not be read or recorded")
        {
            tags, project, demo, model, span, duration, width, height,
        };
        command.SetAction(async parse =>
        {
            var cli = context(parse);
            var path = parse.GetValue(project)!;
            var load = ProjectFile.Load(path);
            if (!load.Ok)
            {
                return ProjectProblemsView.Report(cli, path, load, "no trend drawn");
            }

            if (!TagArguments.TryResolve(load.Project, parse.GetValue(tags) ?? [], out var named, out var tagError))
            {
                return cli.Fail(ExitCodes.BadInput, tagError);
            }

            var (columns, rows, seconds) = (parse.GetValue(width), parse.GetValue(height), parse.GetValue(duration));
            if (!TimeRange.TryDuration(parse.GetValue(span) ?? string.Empty, out var window) || columns is < 10 or > 500 || rows is < 1 or > 40 || seconds is <= 0)
            {
                return cli.Fail(ExitCodes.BadInput, "--span must be like 10m, --width 10-500, --height 1-40, --duration positive");
            }

            var isDemo = parse.GetValue(demo);
            await using var historian = Historian.Historian.Open(cli.History.DatabaseFor(path, isDemo), load.Project, TimeProvider.System, cli.Log, "opanel trend");
            var (opened, openError) = await WatchSession.TryOpenAsync(load.Project, isDemo, parse.GetValue(model), cli.Log, cli.Journal, historian);
            if (opened is null)
            {
                return cli.Fail(ExitCodes.BadInput, openError ?? "the demo line did not start");
            }

            var plan = new TrendPlan(named, window, columns, rows);
            string? unreadable;
            List<string> offline;
            await using (var session = opened)
            {
                using var stop = new StopSignals(seconds is { } s ? TimeSpan.FromSeconds(s) : null);
                unreadable = await RunAsync(cli, session, historian, plan, stop.Token);
                var states = session.Project.Stations.Select(s => (Station: s, Status: session.Line.StatusOf(s.Address))).ToList();
                offline = states.All(s => s.Status?.State != Core.Polling.StationState.Online)
                    ? [.. states.Select(s => Offline(s.Station, s.Status))]
                    : [];
            }

            await historian.FlushAsync();
            List<string> problems = [.. offline];
            var notRecorded = historian.Problem;
            if (unreadable is not null)
            {
                // A damaged file usually fails the writer with the same words: said once.
                problems.Add(unreadable == notRecorded ? $"no trend drawn, history not recorded: {unreadable}" : $"no trend drawn: {unreadable}");
            }

            if (notRecorded is not null && notRecorded != unreadable)
            {
                problems.Add($"history not recorded: {notRecorded}");
            }

            return problems.Count == 0 ? ExitCodes.Ok : End(cli, problems);
        });
        return command;
    }

    /// <summary>"Filler offline, last error: station 2: serial port COM3: open failed ...", as the chart's station line says it.</summary>
    private static string Offline(ProjectStation station, Core.Polling.StationStatus? status)
    {
        var state = (status?.State ?? Core.Polling.StationState.Unknown).ToString().ToLowerInvariant();
        return new TrendStation(station.Name, station.Address.Address, state, LinkFailure.WithoutKind(status?.LastError, status?.LastErrorKind)).Problem!;
    }

    /// <summary>
    /// Why trend ends with exit 2: each reason on stderr, or with --json one more JSON line (the stream stays one object
    /// per line) with all of them.
    /// </summary>
    private static int End(CliContext cli, IReadOnlyList<string> problems)
    {
        if (cli.Json)
        {
            cli.WriteJsonLine(new { ok = false, error = string.Join("; ", problems), errors = problems });
        }
        else
        {
            foreach (var problem in problems)
            {
                cli.Error.WriteLine($"opanel: {problem}");
            }
        }

        return ExitCodes.LinkFailure;
    }

    /// <summary>Draws until <paramref name="stop"/>; the history database's error when it cannot be read (then nothing more is drawn), else null.</summary>
    private static async Task<string?> RunAsync(CliContext cli, WatchSession session, Historian.Historian historian, TrendPlan plan, CancellationToken stop)
    {
        var console = TrendRenderer.ConsoleFor(cli.Out, cli.IsTerminal && !cli.Json, plan.Width);
        async Task<TrendFrame> NextAsync()
        {
            await historian.FlushAsync();
            return TrendFrame.Build(historian.Reader, plan.Tags, session.Line, session.Line.StatusOf, TimeProvider.System.GetUtcNow(), plan.Span, plan.Width, plan.Height);
        }

        try
        {
            if (cli.IsTerminal && !cli.Json)
            {
                await console.Live(TrendRenderer.Render(await NextAsync())).StartAsync(async live =>
                {
                    while (true)
                    {
                        await Task.Delay(RedrawPeriod, TimeProvider.System, stop);
                        live.UpdateTarget(TrendRenderer.Render(await NextAsync()));
                    }
                });
            }

            while (true)
            {
                await Task.Delay(RedrawPeriod, TimeProvider.System, stop);
                if (cli.Json)
                {
                    var frame = await NextAsync();
                    cli.WriteJsonLine(new
                    {
                        time = frame.To,
                        stations = frame.Stations.Select(s => new { name = s.Name, station = s.Station, state = s.State, lastError = s.LastError }),
                        tags = frame.Panels.Select(p => new { name = p.Name, value = p.Value, quality = p.Quality, min = p.Min, max = p.Max, gaps = p.Gaps }),
                    });
                }
            }
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
            // Ctrl+C, SIGTERM or --duration: the normal end.
        }
        catch (HistoryException failure)
        {
            // A damaged or foreign file: the chart has nothing to stand on, so it ends here and says so (exit 2).
            return failure.Message;
        }

        if (!cli.IsTerminal && !cli.Json)
        {
            try
            {
                console.Write(TrendRenderer.Render(await NextAsync()));
            }
            catch (HistoryException failure)
            {
                return failure.Message;
            }
        }

        return null;
    }

    private sealed record TrendPlan(IReadOnlyList<NamedTag> Tags, TimeSpan Span, int Width, int Height);
}
