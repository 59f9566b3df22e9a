using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Simulator.Hosting;
using Serilog;

namespace OperatorPanel.Cli.Watch;

/// <summary>
/// A project's line opened for watching: per <see cref="ProjectBus"/> one link (the real port, or an in-process demo line
/// simulating the bus's stations) and one polling engine, continuous at the project's minimum period or on demand.
/// </summary>
internal sealed class WatchSession : IAsyncDisposable
{
    private readonly List<BusRun> _buses;

    private WatchSession(PanelProject project, List<BusRun> buses)
    {
        Project = project;
        _buses = buses;
    }

    public PanelProject Project { get; }

    public IReadOnlyList<BusRun> Buses => _buses;

    /// <summary>Opens every bus; false with the reason (and every bus opened so far closed) when a demo line cannot start.</summary>
    public static async Task<(WatchSession? Session, string? Error)> TryOpenAsync(PanelProject project, bool demo, SimulationModel model, ILogger log)
    {
        var buses = new List<BusRun>();
        foreach (var bus in ProjectBus.Of(project))
        {
            if (!LinkSession.TryOpen(bus.Serial, demo ? [.. bus.Stations.Select(s => (s.Address, s.Cpu))] : null, model, log, null, out var session, out var error))
            {
                await new WatchSession(project, buses).DisposeAsync();
                return (null, error);
            }

            var engine = project.Refresh.Mode == RefreshMode.Continuous
                ? EngineRun.Start(session.Link, bus.Plan(), RefreshMode.Continuous, project.Refresh.MinimumPeriod, log)
                : EngineRun.OnDemand(session.Link, bus.Plan(), log);
            buses.Add(new BusRun(bus, session, engine));
        }

        return (new WatchSession(project, buses), null);
    }

    /// <summary>
    /// Waits for one full cycle of every bus: in continuous mode the next regular one, on demand one asked for now.
    /// </summary>
    public Task RefreshAsync(CancellationToken cancellationToken) =>
        Task.WhenAll(_buses.Select(b => b.Engine.Engine.RequestRefreshAsync(cancellationToken)));

    public async ValueTask DisposeAsync()
    {
        foreach (var bus in _buses)
        {
            await bus.Engine.DisposeAsync();
            await bus.Link.DisposeAsync();
        }
    }

    /// <summary>One bus of the line with its link and engine.</summary>
    internal sealed record BusRun(ProjectBus Bus, LinkSession Link, EngineRun Engine);
}
