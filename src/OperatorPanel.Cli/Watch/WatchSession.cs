using System.Collections.Concurrent;
using OperatorPanel.Cli.Commands;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.Demo;
using OperatorPanel.Simulator.Hosting;
using Serilog;

namespace OperatorPanel.Cli.Watch;

/// <summary>
/// A project's <see cref="ProjectLine"/> opened for watching, over the project's serial ports or an in-process demo line
/// per bus (<see cref="DemoLineConnector"/>); continuous at the project's minimum period, or on demand with plain READs.
/// </summary>
internal sealed class WatchSession : IAsyncDisposable
{
    /// <summary>IDENTIFY attempts per station on opening (each with the link's own retries).</summary>
    private const int IdentifyAttempts = 3;

    private readonly CancellationTokenSource _closing = new();
    private readonly ConcurrentDictionary<Station, string> _handlerChecks = new();
    private Task _identifying = Task.CompletedTask;
    private IDisposable? _recording;

    private WatchSession(ProjectLine line) => Line = line;

    public ProjectLine Line { get; }

    public PanelProject Project => Line.Project;

    /// <summary>
    /// What IDENTIFY said of the station's handler against the project: "ok: ...", "MISMATCH ..." (a handler generated
    /// for another CPU, or another CPU on the bus), or why it could not be asked; null until it has been asked.
    /// </summary>
    public string? HandlerCheckOf(Station station) => _handlerChecks.TryGetValue(station, out var check) ? check : null;

    /// <summary>
    /// Opens every bus; false with the reason (and nothing left running) when a demo line cannot start. Writes go on
    /// record in <paramref name="journal"/>, and on connecting the writes earlier programs left cut short on the ports are
    /// settled. With a <paramref name="historian"/> the line's values are recorded from before the first cycle.
    /// </summary>
    public static async Task<(WatchSession? Session, string? Error)> TryOpenAsync(
        PanelProject project, bool demo, SimulationModel model, ILogger log, WriteJournal journal, Historian.Historian? historian = null)
    {
        ILineConnector connector = demo ? new DemoLineConnector(model, log) : new SerialLineConnector(log);
        var options = new ProjectLineOptions
        {
            LinkOptionsFor = serial => LinkSession.OptionsFor(serial, scanAllowance: null, demo),
            PpiOptionsFor = serial => LinkSession.PpiOptionsFor(serial, scanAllowance: null, demo),
            // A triggered watch refreshes once a second at most: registering read lists would only add exchanges.
            UseReadLists = project.Refresh.Mode == RefreshMode.Continuous,
            Journal = journal,
        };
        var line = new ProjectLine(project, options, TimeProvider.System, log);
        var recording = historian?.RecordLine(project, line, line.StatusOf);
        try
        {
            await line.ConnectAsync(connector);
        }
        catch (InvalidOperationException ex) when (demo)
        {
            recording?.Dispose();
            return (null, ex.Message);
        }

        var session = new WatchSession(line) { _recording = recording };
        session._identifying = session.IdentifyEveryStationAsync(log, session._closing.Token);
        return (session, null);
    }

    /// <summary>
    /// Waits for one full cycle of every bus: in continuous mode the next regular one, on demand one asked for now.
    /// </summary>
    public Task RefreshAsync(CancellationToken cancellationToken) => Line.NextCycleAsync(cancellationToken);

    public async ValueTask DisposeAsync()
    {
        await _closing.CancelAsync();
        try
        {
            await _identifying;
        }
        catch (OperationCanceledException)
        {
            // Closed while a station was still being identified: nothing to keep.
        }

        _closing.Dispose();
        _recording?.Dispose();
        await Line.DisposeAsync();
    }

    /// <summary>
    /// IDENTIFY each station through its bus, as the panel does on connecting: the bus learns what the handler has
    /// (READ CHANGES copies, 09 READ CHANGES OF LISTS) and polls accordingly from then on. Not awaited on opening, so
    /// a silent station does not hold up the view; it is polled as before and shows up offline. A v1 handler's message
    /// is logged. What it found is kept for the view (<see cref="HandlerCheckOf"/>): the watch is where a technician sees
    /// that the handler in a PLC was generated for another CPU than the project's.
    /// </summary>
    private async Task IdentifyEveryStationAsync(ILogger log, CancellationToken cancellationToken)
    {
        foreach (var station in Line.Project.Stations)
        {
            if (station.Link.Protocol == LinkProtocol.Ppi)
            {
                // No handler to identify: what PPI tells about the CPU instead (one job; a silent CPU shows offline anyway).
                var outcome = await Line.IdentifyPpiAsync(station.Address, cancellationToken);
                _handlerChecks[station.Address] = PpiIdentifyView.Check(station.Cpu, outcome);
                continue;
            }

            for (var attempt = 1; attempt <= IdentifyAttempts; attempt++)
            {
                LinkReply reply;
                try
                {
                    reply = await Line.IdentifyAsync(station.Address, cancellationToken);
                }
                catch (InvalidOperationException notConnected)
                {
                    _handlerChecks[station.Address] = $"not identified: {notConnected.Message}";
                    log.Warning("{Station}: not identified: {Reason}", station.Address, notConnected.Message);
                    break;
                }

                if (reply is LinkReply.Answered answered)
                {
                    _handlerChecks[station.Address] = HandlerCheck.Describe(station, answered.Response);
                    if (answered.Response is ErrorResponse refused)
                    {
                        log.Warning("{Station}: IDENTIFY refused: {Error}", station.Address, refused.Error);
                    }

                    break;
                }

                var failure = reply.Failure!;
                if (failure.Kind == PlcErrorKind.HandlerOutdated || attempt == IdentifyAttempts)
                {
                    _handlerChecks[station.Address] = $"not identified: {failure.Message}";
                    log.Warning("{Station}: IDENTIFY failed: {Reason}", station.Address, failure.Message);
                    break;
                }

                log.Debug("{Station}: IDENTIFY attempt {Attempt} failed: {Reason}", station.Address, attempt, failure.Message);
            }
        }
    }
}
