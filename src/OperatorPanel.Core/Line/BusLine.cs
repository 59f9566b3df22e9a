using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using Serilog;

namespace OperatorPanel.Core.Line;

/// <summary>
/// One RS-485 bus while connected: a <see cref="PollingEngine"/> looping in the background on the bus's
/// <see cref="PlcLink"/>. Disposing stops the loop (after its exchange on the wire); the link stays open for the next
/// engine, and its owner closes it.
/// </summary>
public sealed class BusLine : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _loop;

    private BusLine(PlcLink link, PollingEngine engine)
    {
        (Link, Engine) = (link, engine);
        _loop = Task.Run(() => engine.RunAsync(_stop.Token));
    }

    public PlcLink Link { get; }

    public PollingEngine Engine { get; }

    /// <summary>Starts polling <paramref name="plan"/> on <paramref name="link"/>; its writes go on record in <paramref name="audit"/> (PollingEngine.Audit; null records nothing).</summary>
    public static BusLine Start(
        PlcLink link, PollPlan plan, RefreshMode mode, TimeSpan minimumPeriod, bool useReadLists, TimeProvider time, ILogger logger, AuditContext? audit = null) =>
        new(link, new PollingEngine(link, plan, time, logger) { Mode = mode, MinimumPeriod = minimumPeriod, UseReadLists = useReadLists, Audit = audit });

    /// <summary>
    /// One engine cycling on demand with plain READs: what a one-off read or write needs (it refreshes once or twice, so
    /// registering read lists, one more exchange each, would only cost time).
    /// </summary>
    public static BusLine OnDemand(PlcLink link, PollPlan plan, TimeProvider time, ILogger logger, AuditContext? audit = null) =>
        Start(link, plan, RefreshMode.OnDemand, TimeSpan.Zero, useReadLists: false, time, logger, audit);

    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync().ConfigureAwait(false);
        await _loop.ConfigureAwait(false);
        _stop.Dispose();
    }
}
