using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// What one poll cycle read, frame by frame, and the quality rules that turn it into values: all bytes of a value read →
/// Good; a frame refused → Bad; a frame failed on the link → Stale when the value was read before, else Bad. A value split
/// across frames needs all of them.
/// </summary>
internal sealed class CycleReads(PollPlan plan)
{
    private readonly FrameRead[] _reads = new FrameRead[plan.Frames.Length];

    /// <summary>Frames whose READ was attempted (a stored list once, however it was read).</summary>
    public int Sent { get; private set; }

    /// <summary>Attempted frames that got no usable reply or an error reply.</summary>
    public int Failed { get; private set; }

    public void Record(int frame, FrameRead read)
    {
        _reads[frame] = read;
        Sent++;
        Failed += read.Succeeded ? 0 : 1;
    }

    /// <summary>Frames not tried this cycle because their station is offline or resting: failed with its last error.</summary>
    public void MarkOffline(IEnumerable<int> frames, string error)
    {
        foreach (var frame in frames)
        {
            _reads[frame] = FrameRead.Failure(error, stationOffline: true);
        }
    }

    /// <summary>The station's values after this cycle's reads, and the changes subscribers must hear of.</summary>
    public List<ValueChange> Apply(Station station, ValueStore values, DateTimeOffset now)
    {
        ArgumentNullException.ThrowIfNull(values);
        var changes = new List<ValueChange>();
        foreach (var planned in plan.Values.Where(v => v.Item.Station == station))
        {
            var failure = planned.Slices.Select(s => _reads[s.FrameIndex]).FirstOrDefault(r => !r.Succeeded);
            Func<PolledValue, PolledValue> next = failure.Error is not { } error
                ? _ => PolledValue.Good(Assemble(planned), now)
                : old => failure.Refused || !old.HasValue
                    ? old with { Quality = ValueQuality.Bad, Error = error, Timestamp = now }
                    : old with { Quality = ValueQuality.Stale, Error = error };
            if (values.Update(planned.Item, next) is { } change)
            {
                changes.Add(change);
            }
        }

        return changes;
    }

    private ImmutableArray<byte> Assemble(PlannedValue planned)
    {
        var bytes = new List<byte>();
        foreach (var slice in planned.Slices)
        {
            bytes.AddRange(_reads[slice.FrameIndex].Data.AsSpan(slice.DataOffset, slice.Length));
        }

        return ValueStore.Extract(planned.Item.Address, bytes.ToArray());
    }
}
