using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Cli.Bench.History;

/// <summary>
/// The line's value surface without a line: the bench publishes each value a poll cycle would deliver, and the
/// recorder hears it through the same <see cref="ILineValues.Subscribe"/> it uses on a real line.
/// </summary>
internal sealed class BenchLineValues : ILineValues
{
    private readonly Dictionary<WatchedItem, Action<PolledValue>> _subscribers = [];
    private readonly Dictionary<WatchedItem, PolledValue> _values = [];

    public IDisposable Subscribe(Station station, PlcAddress address, Action<PolledValue> onValue)
    {
        var item = new WatchedItem(station, address);
        _subscribers[item] = onValue;
        TryGetValue(station, address, out var now);
        onValue(now);
        return new Unsubscribe(() => _subscribers.Remove(item));
    }

    public bool TryGetValue(Station station, PlcAddress address, out PolledValue value)
    {
        var found = _values.TryGetValue(new WatchedItem(station, address), out var known);
        value = known ?? PolledValue.NotRead(DateTimeOffset.UnixEpoch);
        return found;
    }

    /// <summary>Delivers <paramref name="value"/> when it differs from the last one, as the line delivers changes only.</summary>
    public void Publish(Station station, PlcAddress address, PolledValue value)
    {
        var item = new WatchedItem(station, address);
        if (_values.TryGetValue(item, out var last) && !last.DiffersFrom(value))
        {
            return;
        }

        _values[item] = value;
        if (_subscribers.TryGetValue(item, out var subscriber))
        {
            subscriber(value);
        }
    }

    private sealed class Unsubscribe(Action action) : IDisposable
    {
        public void Dispose() => action();
    }
}
