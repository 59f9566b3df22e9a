using System.CommandLine;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Cli.Hosting;
using OperatorPanel.Cli.Link;
using OperatorPanel.Cli.Watch;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using Spectre.Console;
using Spectre.Console.Rendering;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel watch PROJECT [--demo] [--ppi [--baud B]]</c>: the project's stations live in the terminal, over the project's serial ports or
/// an in-process demo line that simulates every station with its own CPU and the demo process; every recorded value goes into the
/// project's history database from the first cycle (the demo line's into a database of its own).
/// </summary>
internal static class WatchCommand
{
    /// <summary>Triggered projects are refreshed on request; the terminal view asks once a second.</summary>
    private static readonly TimeSpan TriggeredInterval = TimeSpan.FromSeconds(1);

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var file = new Argument<string>("project") { Description = "The .opproj project file" };
        var model = ModelOption.Create();
        var demo = new Option<bool>("--demo") { Description = "Simulate every station in-process (its CPU, running the demo process) instead of opening the ports" };
        var once = new Option<bool>("--once") { Description = "One full refresh, print it and exit" };
        var cycles = new Option<int?>("--cycles") { Description = "Stop after this many full refreshes" };
        var duration = new Option<double?>("--duration") { HelpName = "seconds", Description = "Stop after this many seconds (default: until Ctrl+C)" };
        var ppi = new Option<bool>("--ppi")
        {
            Description = "Read every bus over PPI, the CPU's own protocol, with no handler (a station in STOP or at TERM answers): "
                + "8 data bits, even parity, the cable; the project file is not changed",
        };
        var baud = new Option<int?>("--baud") { Description = "With --ppi: 9600, 19200 or 187500, the CPU's PPI rate (default: the bus's baud when a PPI rate, else 9600)" };
        var command = new Command(
            "watch",
            "Show a project's stations live: link state and counters, inputs and outputs as lamps, tags, active alarms. "
            + "Drawn in place on a terminal, fitted to its size (long lines cut; lamps and tags give way on a low terminal, the title, "
            + "each station's state and its alarms stay); appends a snapshot per refresh (--once, --cycles) or per second elsewhere; --json prints JSON lines. "
            + "Records the values into the project's history (the demo line's into its own) from the first cycle: opanel history prints it. "
            + "Exit codes: 0 done, 1 project problems or bad option, 2 every station offline at the end")
        {
            file, demo, model, once, cycles, duration, ppi, baud,
        };
        command.SetAction(async parse =>
        {
            var cli = context(parse);
            var path = parse.GetValue(file)!;
            var load = ProjectFile.Load(path);
            if (!load.Ok)
            {
                return ProjectProblemsView.Report(cli, path, load, "nothing watched");
            }

            if (!TryReadOverPpi(cli, load.Project, parse.GetValue(ppi), parse.GetValue(baud), out var project, out var ppiError))
            {
                return cli.Fail(ExitCodes.BadInput, ppiError);
            }

            var limit = parse.GetValue(once) ? 1 : parse.GetValue(cycles);
            var seconds = parse.GetValue(duration);
            if (limit is <= 0 || seconds is <= 0)
            {
                return cli.Fail(ExitCodes.BadInput, "--cycles and --duration must be positive");
            }

            await using var historian = Historian.Historian.Open(cli.History.DatabaseFor(path, parse.GetValue(demo)), project, TimeProvider.System, cli.Log, "opanel watch");
            var (opened, openError) = await WatchSession.TryOpenAsync(project, parse.GetValue(demo), parse.GetValue(model), cli.Log, cli.Journal, historian);
            if (opened is null)
            {
                return cli.Fail(ExitCodes.BadInput, openError ?? "the demo line did not start");
            }

            WatchSnapshot last;
            await using (var session = opened)
            {
                foreach (var cutShort in session.Line.ResolvedAtConnect)
                {
                    cli.Error.WriteLine("opanel: " + cutShort.Describe());
                }

                using var stop = new StopSignals(seconds is { } s ? TimeSpan.FromSeconds(s) : null);
                last = cli.IsTerminal && !cli.Json
                    ? await OnTerminalAsync(cli, session, limit, stop.Token)
                    : await RunAsync(cli, session, limit, screen: null, size: null, stop.Token);
            }

            await historian.FlushAsync();
            ReportHistory(cli, historian);
            return last.AllOffline ? ExitCodes.LinkFailure : ExitCodes.Ok;
        });
        return command;
    }

    /// <summary>
    /// --ppi: every bus switched in memory to PPI (PpiFallback, as the panel's Line > Read over PPI), said first (on the
    /// error stream with --json, which stays one object per line); --baud only with --ppi and only a PPI rate.
    /// </summary>
    private static bool TryReadOverPpi(CliContext cli, PanelProject loaded, bool ppi, int? baud, out PanelProject project, [NotNullWhen(false)] out string? error)
    {
        (project, error) = (loaded, null);
        if (!ppi)
        {
            error = baud is null ? null : "--baud needs --ppi: a Freeport bus runs at the project's baud";
            return error is null;
        }

        if (baud is { } b && !PpiFallback.Rates.Contains(b))
        {
            error = $"--baud {b} is not a PPI rate; PPI runs at {string.Join(", ", PpiFallback.Rates)}";
            return false;
        }

        project = PpiFallback.Switch(loaded, portName: null, baud);
        foreach (var link in project.Stations.Select(s => s.Link).DistinctBy(l => l.PortName, StringComparer.OrdinalIgnoreCase))
        {
            (cli.Json ? cli.Error : cli.Out).WriteLine(
                $"reading {link.PortName} over PPI at {PpiFallback.DescribeBaud(link.BaudRate)}: no handler needed, STOP and handler checks are off; the project file is unchanged");
        }

        return true;
    }

    /// <summary>Where the values went: one line after the text view (the JSON stream stays one object per line), and the log.</summary>
    private static void ReportHistory(CliContext cli, Historian.Historian historian)
    {
        if (historian.Problem is { } problem)
        {
            cli.Error.WriteLine($"opanel: history not recorded: {problem}");
        }
        else if (!cli.Json)
        {
            cli.Out.WriteLine($"history: {historian.Written} rows recorded into {historian.DatabasePath} (opanel history --project ... prints them)");
        }

        cli.Log.Information("Watch recorded {Rows} history rows into {Path}", historian.Written, historian.DatabasePath);
    }

    /// <summary>
    /// The live view in place on the terminal: Spectre.Console's live display, each frame fitted to the terminal's size
    /// now (one row spare, so the last line never scrolls the screen); the last frame stays when watch ends.
    /// </summary>
    private static async Task<WatchSnapshot> OnTerminalAsync(CliContext cli, WatchSession session, int? limit, CancellationToken stop)
    {
        var console = AnsiConsole.Console;
        WatchSnapshot? last = null;
        await console.Live(new Text(string.Empty))
            .AutoClear(false)
            .Overflow(VerticalOverflow.Crop)
            .Cropping(VerticalOverflowCropping.Bottom)
            .StartAsync(async live => last = await RunAsync(
                cli,
                session,
                limit,
                frame =>
                {
                    live.UpdateTarget(frame);
                    live.Refresh();
                },
                () => (console.Profile.Width, console.Profile.Height - 1),
                stop));
        return last!;
    }

    private static async Task<WatchSnapshot> RunAsync(
        CliContext cli, WatchSession session, int? limit, Action<IRenderable>? screen, Func<(int Width, int Height)>? size, CancellationToken stop)
    {
        var time = TimeProvider.System;
        var output = new LiveOutput(cli, everyCycle: limit is not null, time, screen, size);
        long cycle = 0;
        WatchSnapshot Snapshot() => SnapshotBuilder.Build(session, cycle, time.GetLocalNow());
        try
        {
            while (cycle < (limit ?? long.MaxValue))
            {
                await session.RefreshAsync(stop);
                cycle++;
                output.CycleCompleted(Snapshot);
                if (session.Project.Refresh.Mode == RefreshMode.OnDemand && cycle < (limit ?? long.MaxValue))
                {
                    await Task.Delay(TriggeredInterval, time, stop);
                }
            }
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
            // Ctrl+C, SIGTERM or --duration: the normal end of an open-ended watch.
        }

        output.Finish(Snapshot);
        return Snapshot();
    }
}
