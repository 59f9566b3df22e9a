using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using Serilog;

namespace OperatorPanel.ViewModels.Session;

/// <summary>One bus of a connected project: its link (kept while connected) and a polling engine looping on it.</summary>
internal sealed class BusRun : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly IDisposable _subscription;
    private readonly Task _loop;

    private BusRun(ProjectBus bus, PlcLink link, PollingEngine engine, Action<IReadOnlyList<ValueChange>> onChanges)
    {
        (Bus, Link, Engine) = (bus, link, engine);
        _subscription = engine.Subscribe(onChanges);
        _loop = Task.Run(() => engine.RunAsync(_stop.Token));
    }

    public ProjectBus Bus { get; }

    public PlcLink Link { get; }

    public PollingEngine Engine { get; }

    public static BusRun Start(
        ProjectBus bus, PlcLink link, RefreshMode mode, TimeSpan minimumPeriod, TimeProvider time, ILogger logger,
        Action<IReadOnlyList<ValueChange>> onChanges) =>
        new(bus, link, new PollingEngine(link, bus.Plan(), time, logger) { Mode = mode, MinimumPeriod = minimumPeriod }, onChanges);

    /// <summary>Stops the engine's loop; the link stays open for the next engine (the session disposes it).</summary>
    public async ValueTask DisposeAsync()
    {
        _subscription.Dispose();
        await _stop.CancelAsync();
        await _loop;
        _stop.Dispose();
    }
}
