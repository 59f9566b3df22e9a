using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// What each watched address held over a run, of whatever width: its value at the start and after every change that
/// touched one of its bytes, each with the change's time (TimeProvider ticks). A word or double word is read from the
/// bytes as they stood together after each change, so a value made of bytes that never stood there together (the
/// widened-window defect: MW30 shown with MB28-MB29) was never held.
/// </summary>
internal sealed class ItemHistory
{
    private readonly Dictionary<PlcAddress, List<(long At, ImmutableArray<byte> Value)>> _timelines;

    public ItemHistory(IEnumerable<PlcAddress> items, MemoryImage initial)
    {
        ArgumentNullException.ThrowIfNull(items);
        ArgumentNullException.ThrowIfNull(initial);
        _timelines = items.Distinct().ToDictionary(a => a, a => new List<(long, ImmutableArray<byte>)> { (long.MinValue, initial.Read(a)) });
    }

    /// <summary>Notes the values after <paramref name="change"/>, already applied to <paramref name="image"/>.</summary>
    public void Record(MemoryChange change, MemoryImage image)
    {
        ArgumentNullException.ThrowIfNull(change);
        ArgumentNullException.ThrowIfNull(image);
        foreach (var (address, timeline) in _timelines)
        {
            if (SoakRegion.AreaOf(address) == change.Area && address.ByteOffset <= change.Last && address.LastByte >= change.First)
            {
                timeline.Add((change.Timestamp, image.Read(address)));
            }
        }
    }

    /// <summary>True when <paramref name="address"/> held <paramref name="value"/> at some moment from <paramref name="from"/> to <paramref name="until"/>.</summary>
    public bool WasHeld(PlcAddress address, ImmutableArray<byte> value, long from, long until)
    {
        var timeline = _timelines[address];
        for (var i = 0; i < timeline.Count; i++)
        {
            var ends = i + 1 < timeline.Count ? timeline[i + 1].At : long.MaxValue;
            if (timeline[i].At <= until && ends > from && timeline[i].Value.AsSpan().SequenceEqual(value.AsSpan()))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>True when <paramref name="address"/> held <paramref name="value"/> from <paramref name="from"/> to <paramref name="until"/> without a break.</summary>
    public bool HeldThroughout(PlcAddress address, ImmutableArray<byte> value, long from, long until)
    {
        var timeline = _timelines[address];
        for (var i = 0; i < timeline.Count; i++)
        {
            var ends = i + 1 < timeline.Count ? timeline[i + 1].At : long.MaxValue;
            if (timeline[i].At <= until && ends > from && !timeline[i].Value.AsSpan().SequenceEqual(value.AsSpan()))
            {
                return false;
            }
        }

        return true;
    }
}
