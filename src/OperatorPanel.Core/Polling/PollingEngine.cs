using System.Collections.Concurrent;
using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Writes;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// Keeps the watched values of a <see cref="PollPlan"/> up to date over an <see cref="IPlcLink"/> and carries the
/// operator's writes, in the two modes of seed 000 §7. One loop (<see cref="RunAsync"/>) does all link traffic, so one
/// request is on the wire at a time; queued writes go ahead of the next READ. Failures never escape the loop: they
/// become value qualities, <see cref="StationStatus"/>es and log entries, and polling goes on.
/// All waiting uses the injected <see cref="TimeProvider"/>.
/// </summary>
public sealed partial class PollingEngine
{
    private readonly IPlcLink _link;
    private readonly PollPlan _plan;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;
    private readonly ValueStore _values;
    private readonly StationTracker _stations;
    private readonly WakeSignal _wake = new();
    private readonly ConcurrentQueue<PendingWrite> _writes = new();
    private readonly Lock _gate = new();
    private readonly List<TaskCompletionSource<PollResult>> _refreshWaiters = [];
    private ImmutableArray<Action<IReadOnlyList<ValueChange>>> _subscribers = [];
    private RefreshMode _mode = RefreshMode.Continuous;
    private TimeSpan _minimumPeriod = TimeSpan.FromMilliseconds(100);
    private PollResult? _lastResult;
    private int _running;

    public PollingEngine(IPlcLink link, PollPlan plan, TimeProvider? timeProvider = null, ILogger? logger = null)
    {
        ArgumentNullException.ThrowIfNull(link);
        ArgumentNullException.ThrowIfNull(plan);
        _link = link;
        _plan = plan;
        _time = timeProvider ?? TimeProvider.System;
        _logger = (logger ?? Logger.None).ForContext<PollingEngine>();
        _values = new ValueStore(plan.Values.Select(v => v.Item), _time.GetUtcNow());
        _stations = new StationTracker(_time, _logger);
        _listIds = ReadListAssignment.For(plan);
    }

    public PollPlan Plan => _plan;

    /// <summary>Switchable while running; the loop notices at once.</summary>
    public RefreshMode Mode
    {
        get { lock (_gate) { return _mode; } }
        set { lock (_gate) { _mode = value; } _wake.Set(); }
    }

    /// <summary>In continuous mode a cycle never starts sooner than this after the previous cycle started. Default 100 ms.</summary>
    public TimeSpan MinimumPeriod
    {
        get { lock (_gate) { return _minimumPeriod; } }
        set
        {
            ArgumentOutOfRangeException.ThrowIfLessThan(value, TimeSpan.Zero);
            lock (_gate) { _minimumPeriod = value; }
            _wake.Set();
        }
    }

    public PollResult? LastResult
    {
        get { lock (_gate) { return _lastResult; } }
    }

    /// <summary>
    /// Calls <paramref name="onChanges"/> with every batch of changed values (value or quality), once per cycle and
    /// once per write read-back, on the polling loop's thread; marshal to the UI yourself. A throwing subscriber is
    /// logged and stays subscribed. Dispose the result to unsubscribe. Outside Core, values come from Line/ILineValues.
    /// </summary>
    internal IDisposable Subscribe(Action<IReadOnlyList<ValueChange>> onChanges)
    {
        ArgumentNullException.ThrowIfNull(onChanges);
        lock (_gate) { _subscribers = _subscribers.Add(onChanges); }
        return new Subscription(() => { lock (_gate) { _subscribers = _subscribers.Remove(onChanges); } });
    }

    /// <summary>The latest value of a watched address; false when the plan does not watch it.</summary>
    public bool TryGetValue(Station station, PlcAddress address, out PolledValue value) =>
        _values.TryGet(new WatchedItem(station, address), out value);

    /// <summary>The station's link state; for a silent station resting between tries, when it is tried next.</summary>
    public StationStatus GetStationStatus(Station station)
    {
        var status = _stations.Get(station);
        return NextTry(station, status) is { } next ? status with { NextTryAt = next } : status;
    }

    /// <summary>The panel stopped the station (Stop/RemoteStop confirmed it): its silence is no longer news.</summary>
    public void NoteStoppedByPanel(Station station) => _stations.RecordStoppedByPanel(station);

    /// <summary>
    /// Asks for one full cycle and returns its result. In <see cref="RefreshMode.OnDemand"/> this is what makes the
    /// engine poll; in continuous mode it completes with the next regular cycle. Cancelled when polling stops first.
    /// </summary>
    public Task<PollResult> RequestRefreshAsync(CancellationToken cancellationToken = default)
    {
        var waiter = new TaskCompletionSource<PollResult>(TaskCreationOptions.RunContinuationsAsynchronously);
        cancellationToken.Register(() => waiter.TrySetCanceled(cancellationToken));
        lock (_gate) { _refreshWaiters.Add(waiter); }
        _wake.Set();
        return waiter.Task;
    }

    private void Publish(List<ValueChange> changes)
    {
        if (changes.Count == 0)
        {
            return;
        }

        ImmutableArray<Action<IReadOnlyList<ValueChange>>> subscribers;
        lock (_gate) { subscribers = _subscribers; }
        var batch = changes.AsReadOnly();
        foreach (var subscriber in subscribers)
        {
            try
            {
                subscriber(batch);
            }
            catch (Exception exception)
            {
                _logger.Error(exception, "A value subscriber threw; polling continues");
            }
        }
    }

    private sealed class Subscription(Action unsubscribe) : IDisposable
    {
        private Action? _unsubscribe = unsubscribe;

        public void Dispose() => Interlocked.Exchange(ref _unsubscribe, null)?.Invoke();
    }
}
