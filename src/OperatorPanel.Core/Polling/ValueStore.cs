using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Polling;

/// <summary>The latest <see cref="PolledValue"/> per watched (station, address); written by the polling loop, read by anyone.</summary>
internal sealed class ValueStore
{
    private readonly Lock _lock = new();
    private readonly Dictionary<WatchedItem, PolledValue> _values = [];

    public ValueStore(IEnumerable<WatchedItem> items, DateTimeOffset now)
    {
        foreach (var item in items)
        {
            _values[item] = PolledValue.NotRead(now);
        }
    }

    public bool TryGet(WatchedItem item, out PolledValue value)
    {
        lock (_lock)
        {
            return _values.TryGetValue(item, out value!);
        }
    }

    /// <summary>Replaces the value by <paramref name="next"/>(old); returns the change when subscribers must hear of it.</summary>
    public ValueChange? Update(WatchedItem item, Func<PolledValue, PolledValue> next)
    {
        lock (_lock)
        {
            var previous = _values[item];
            var current = next(previous);
            _values[item] = current;
            return previous.DiffersFrom(current) ? new ValueChange(item.Station, item.Address, previous, current) : null;
        }
    }

    /// <summary>Stores fresh bytes of one area (a write's read-back) into every watched address lying wholly inside them.</summary>
    public List<ValueChange> Apply(Station station, MemoryArea area, int offset, ImmutableArray<byte> bytes, DateTimeOffset now)
    {
        List<WatchedItem> inside;
        lock (_lock)
        {
            inside = [.. _values.Keys.Where(i => i.Station == station
                && i.Address.Area == area
                && i.Address.ByteOffset >= offset
                && i.Address.LastByte < offset + bytes.Length)];
        }

        var changes = new List<ValueChange>();
        foreach (var item in inside)
        {
            var raw = Extract(item.Address, bytes.AsSpan()[(item.Address.ByteOffset - offset)..]);
            if (Update(item, _ => PolledValue.Good(raw, now)) is { } change)
            {
                changes.Add(change);
            }
        }

        return changes;
    }

    /// <summary>The address's bytes from a buffer starting at its first byte; a bit becomes 00 or 01.</summary>
    public static ImmutableArray<byte> Extract(PlcAddress address, ReadOnlySpan<byte> bytes) => address.Bit is { } bit
        ? [(byte)((bytes[0] >> bit) & 1)]
        : [.. bytes[..address.Width.ByteCount()]];
}
