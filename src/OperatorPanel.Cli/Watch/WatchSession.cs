using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
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
    private Task _identifying = Task.CompletedTask;

    private WatchSession(ProjectLine line) => Line = line;

    public ProjectLine Line { get; }

    public PanelProject Project => Line.Project;

    /// <summary>Opens every bus; false with the reason (and nothing left running) when a demo line cannot start.</summary>
    public static async Task<(WatchSession? Session, string? Error)> TryOpenAsync(PanelProject project, bool demo, SimulationModel model, ILogger log)
    {
        ILineConnector connector = demo ? new DemoLineConnector(model, log) : new SerialLineConnector();
        var options = new ProjectLineOptions
        {
            LinkOptionsFor = serial => LinkSession.OptionsFor(serial, scanAllowance: null, demo),
            // A triggered watch refreshes once a second at most: registering read lists would only add exchanges.
            UseReadLists = project.Refresh.Mode == RefreshMode.Continuous,
        };
        var line = new ProjectLine(project, options, TimeProvider.System, log);
        try
        {
            await line.ConnectAsync(connector);
        }
        catch (InvalidOperationException ex) when (demo)
        {
            return (null, ex.Message);
        }

        var session = new WatchSession(line);
        session._identifying = IdentifyEveryStationAsync(line, log, session._closing.Token);
        return (session, null);
    }

    /// <summary>
    /// Waits for one full cycle of every bus: in continuous mode the next regular one, on demand one asked for now.
    /// </summary>
    public Task RefreshAsync(CancellationToken cancellationToken) => Line.RefreshAsync(cancellationToken);

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
        await Line.DisposeAsync();
    }

    /// <summary>
    /// IDENTIFY each station beside the polling, as the panel does on connecting: the engine learns what the handler has
    /// (READ CHANGES copies, 09 READ CHANGES OF LISTS) and polls accordingly from then on. Not awaited on opening, so
    /// a silent station does not hold up the view; it is polled as before and shows up offline. A v1 handler's message
    /// is logged.
    /// </summary>
    private static async Task IdentifyEveryStationAsync(ProjectLine line, ILogger log, CancellationToken cancellationToken)
    {
        foreach (var station in line.Project.Stations)
        {
            for (var attempt = 1; attempt <= IdentifyAttempts; attempt++)
            {
                try
                {
                    if (await line.IdentifyAsync(station.Address, cancellationToken) is ErrorResponse refused)
                    {
                        log.Warning("{Station}: IDENTIFY refused: {Error}", station.Address, refused.Error);
                    }

                    break;
                }
                catch (PlcCommunicationException failure) when (failure.Kind == PlcErrorKind.HandlerProtocolV1 || attempt == IdentifyAttempts)
                {
                    log.Warning("{Station}: IDENTIFY failed: {Reason}", station.Address, failure.Message);
                    break;
                }
                catch (InvalidOperationException notConnected)
                {
                    log.Warning("{Station}: not identified: {Reason}", station.Address, notConnected.Message);
                    break;
                }
                catch (PlcCommunicationException failure)
                {
                    log.Debug("{Station}: IDENTIFY attempt {Attempt} failed: {Reason}", station.Address, attempt, failure.Message);
                }
            }
        }
    }
}
