using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.TestKit;

/// <summary>
/// A line's values without a line: subscribers by address, as ProjectLine keeps them; <see cref="Publish"/> hands each
/// change to the subscribers of its address, in batch order, on the calling thread.
/// </summary>
public sealed class FakeLineValues : ILineValues
{
    private readonly Dictionary<WatchedItem, ImmutableArray<Action<PolledValue>>> _subscribers = [];
    private readonly Dictionary<WatchedItem, PolledValue> _values = [];

    public IDisposable Subscribe(Station station, PlcAddress address, Action<PolledValue> onValue)
    {
        var item = new WatchedItem(station, address);
        _subscribers[item] = _subscribers.GetValueOrDefault(item, []).Add(onValue);
        TryGetValue(station, address, out var now);
        onValue(now);
        return new Unsubscribe(() => _subscribers[item] = _subscribers[item].Remove(onValue));
    }

    public bool TryGetValue(Station station, PlcAddress address, out PolledValue value)
    {
        if (_values.TryGetValue(new WatchedItem(station, address), out value!))
        {
            return true;
        }

        value = PolledValue.NotRead(default);
        return false;
    }

    public void Publish(IReadOnlyList<ValueChange> changes)
    {
        foreach (var change in changes)
        {
            var item = new WatchedItem(change.Station, change.Address);
            _values[item] = change.Current;
            foreach (var subscriber in _subscribers.GetValueOrDefault(item, []))
            {
                subscriber(change.Current);
            }
        }
    }

    private sealed class Unsubscribe(Action action) : IDisposable
    {
        public void Dispose() => action();
    }
}
