using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using Serilog;

namespace OperatorPanel.Cli.Link;

/// <summary>A <see cref="PollingEngine"/> with its loop running in the background until disposed.</summary>
internal sealed class EngineRun : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _loop;

    private EngineRun(PollingEngine engine)
    {
        Engine = engine;
        _loop = Task.Run(() => engine.RunAsync(_stop.Token));
    }

    public PollingEngine Engine { get; }

    public static EngineRun Start(IPlcLink link, PollPlan plan, RefreshMode mode, TimeSpan minimumPeriod, ILogger log) =>
        new(new PollingEngine(link, plan, TimeProvider.System, log) { Mode = mode, MinimumPeriod = minimumPeriod });

    /// <summary>
    /// One engine cycling on demand: what read and write need. They refresh once or twice, so registering read lists
    /// (one more exchange each) would only cost time: plain READs.
    /// </summary>
    public static EngineRun OnDemand(IPlcLink link, PollPlan plan, ILogger log) =>
        new(new PollingEngine(link, plan, TimeProvider.System, log) { Mode = RefreshMode.OnDemand, MinimumPeriod = TimeSpan.Zero, UseReadLists = false });

    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync();
        await _loop;
        _stop.Dispose();
    }
}
