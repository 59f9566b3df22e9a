using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Core.Line;

/// <summary>
/// The line's values, the one publish/subscribe layer between the buses and the windows: subscribers by watched item, so
/// a bus's batch of changes reaches exactly the subscribers of the changed addresses (a dictionary look-up per change, no
/// scan). Connect, disconnect, another project or a new plan push every subscriber its value now, so nobody ever has to
/// pull. A value is read and handed on under one lock, so a value read before a bus batch can never be delivered after
/// it (it would show "not read yet" over a good value). Every delivery ends with <see cref="StateChanged"/>.
/// </summary>
public sealed partial class ProjectLine : ILineValues
{
    private readonly Lock _gate = new();
    private readonly Dictionary<WatchedItem, ImmutableArray<Action<PolledValue>>> _subscribers = [];

    /// <summary>
    /// Station states, link counters or the line itself may have changed: raised through
    /// <see cref="ProjectLineOptions.Deliver"/> (the UI thread in the panel) after every cycle and every job (write,
    /// IDENTIFY, STOP) of every bus, and on connect, disconnect and a new project; after the values of the same moment.
    /// The one trigger of the panel's status bar.
    /// </summary>
    public event EventHandler? StateChanged;

    public IDisposable Subscribe(Station station, PlcAddress address, Action<PolledValue> onValue)
    {
        ArgumentNullException.ThrowIfNull(onValue);
        var item = new WatchedItem(station, address);
        lock (_gate)
        {
            _subscribers[item] = _subscribers.GetValueOrDefault(item, []).Add(onValue);
            TryGetValue(station, address, out var now);
            onValue(now);
        }

        return new Subscription(() =>
        {
            lock (_gate)
            {
                var left = _subscribers[item].Remove(onValue);
                if (left.IsEmpty)
                {
                    _subscribers.Remove(item);
                }
                else
                {
                    _subscribers[item] = left;
                }
            }
        });
    }

    public bool TryGetValue(Station station, PlcAddress address, out PolledValue value)
    {
        if (BusOf(station) is { } bus)
        {
            return bus.TryGetValue(station, address, out value);
        }

        value = PolledValue.NotRead(_time.GetUtcNow());
        return false;
    }

    /// <summary>On a polling loop's thread, after each cycle and job: one bus batch, routed by address and delivered whole.</summary>
    private void OnBusChanges(IReadOnlyList<ValueChange> changes)
    {
        var calls = new List<(Action<PolledValue> Subscriber, PolledValue Value)>();
        lock (_gate)
        {
            foreach (var change in changes)
            {
                if (_subscribers.TryGetValue(new WatchedItem(change.Station, change.Address), out var subscribers))
                {
                    calls.AddRange(subscribers.Select(s => (s, change.Current)));
                }
            }

            Deliver(calls);
        }
    }

    /// <summary>Every subscriber gets its value now: after connect, disconnect, another project or a new plan.</summary>
    private void PushAll()
    {
        lock (_gate)
        {
            var calls = new List<(Action<PolledValue> Subscriber, PolledValue Value)>();
            foreach (var (item, subscribers) in _subscribers)
            {
                TryGetValue(item.Station, item.Address, out var now);
                calls.AddRange(subscribers.Select(s => (s, now)));
            }

            Deliver(calls);
        }
    }

    /// <summary>One batch: each subscriber on its own (one that throws is logged, the others still hear), then the state.</summary>
    private void Deliver(List<(Action<PolledValue> Subscriber, PolledValue Value)> calls) =>
        _options.Deliver(() =>
        {
            foreach (var (subscriber, value) in calls)
            {
                try
                {
                    subscriber(value);
                }
                catch (Exception exception)
                {
                    _logger.Error(exception, "A value subscriber threw; the others still hear the batch");
                }
            }

            StateChanged?.Invoke(this, EventArgs.Empty);
        });

    private sealed class Subscription(Action unsubscribe) : IDisposable
    {
        private Action? _unsubscribe = unsubscribe;

        public void Dispose() => Interlocked.Exchange(ref _unsubscribe, null)?.Invoke();
    }
}
