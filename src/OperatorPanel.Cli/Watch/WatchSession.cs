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

        await IdentifyEveryStationAsync(line, log);
        return (new WatchSession(line), null);
    }

    /// <summary>
    /// IDENTIFY each station once, as the panel does on connecting: the engine learns what the handler has (READ
    /// CHANGES copies, 09 READ CHANGES OF LISTS) and polls accordingly. A station that does not answer is polled as
    /// before and shows up offline; a v1 handler's message is logged.
    /// </summary>
    private static async Task IdentifyEveryStationAsync(ProjectLine line, ILogger log)
    {
        foreach (var station in line.Project.Stations)
        {
            try
            {
                if (await line.IdentifyAsync(station.Address) is ErrorResponse refused)
                {
                    log.Warning("{Station}: IDENTIFY refused: {Error}", station.Address, refused.Error);
                }
            }
            catch (PlcCommunicationException failure)
            {
                log.Warning("{Station}: IDENTIFY failed: {Reason}", station.Address, failure.Message);
            }
        }
    }

    /// <summary>
    /// Waits for one full cycle of every bus: in continuous mode the next regular one, on demand one asked for now.
    /// </summary>
    public Task RefreshAsync(CancellationToken cancellationToken) => Line.RefreshAsync(cancellationToken);

    public ValueTask DisposeAsync() => Line.DisposeAsync();
}
