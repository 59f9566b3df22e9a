using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>Chooses which gaps between one station's byte ranges to read over, by the cost of the packed result.</summary>
internal static class RangeMerger
{
    /// <summary>Packed plans priced exactly, out of the bridge counts the estimate ranks best.</summary>
    private const int ExactCandidates = 6;

    /// <summary>
    /// Coalesces overlapping and touching spans, then bridges the k smallest gaps for the k that gives the cheapest
    /// packed plan (on a tie, the one reading fewer bytes). Every k is first priced by an estimate in one sweep (frames
    /// from the item and capacity bounds, items counted after the 119-byte split); only the best few are packed and
    /// priced exactly, so planning stays O(n log n) instead of packing once per gap. Returned ranges are not split yet:
    /// how long a block may be depends on the tail the lists take.
    /// </summary>
    public static List<ReadItem> Cheapest(IEnumerable<ReadItem> spans, PollCostModel model, FrameCapacity capacity)
    {
        var ranges = Coalesce(spans);
        var gaps = Enumerable.Range(0, Math.Max(0, ranges.Count - 1))
            .Where(i => ranges[i].Area == ranges[i + 1].Area)
            .OrderBy(i => ranges[i + 1].Offset - End(ranges[i])).ThenBy(i => ranges[i].Area).ThenBy(i => ranges[i].Offset)
            .ToArray();
        var estimates = Estimate(ranges, gaps, model, capacity);
        var candidates = Enumerable.Range(0, estimates.Length).OrderBy(k => estimates[k]).ThenBy(k => k).Take(ExactCandidates).Order();
        List<ReadItem> best = [];
        var bestCost = int.MaxValue;
        foreach (var k in candidates)
        {
            var bridged = Bridge(ranges, gaps.AsSpan(0, k));
            var cost = FramePacker.Pack(Split(bridged, capacity.MaxBlockLength), capacity).Sum(f => model.FrameCost(f.Length, f.Sum(i => i.Length)));
            if (cost < bestCost)
            {
                best = bridged;
                bestCost = cost;
            }
        }

        return best;
    }

    /// <summary>Coalesced ranges in area and offset order: overlapping and touching spans joined.</summary>
    public static List<ReadItem> Coalesce(IEnumerable<ReadItem> spans)
    {
        var result = new List<ReadItem>();
        foreach (var span in BlockOrder.Sorted(spans, BlockOrder.ByAddress))
        {
            if (result.Count > 0 && result[^1].Area == span.Area && span.Offset <= End(result[^1]))
            {
                var last = result[^1];
                result[^1] = last with { Length = Math.Max(End(last), End(span)) - last.Offset };
            }
            else
            {
                result.Add(span);
            }
        }

        return result;
    }

    /// <summary>Cuts ranges longer than <paramref name="maxLength"/> into full-size pieces and a remainder.</summary>
    public static ImmutableArray<ReadItem> Split(IEnumerable<ReadItem> ranges, int maxLength)
    {
        var result = ImmutableArray.CreateBuilder<ReadItem>();
        foreach (var range in ranges)
        {
            for (var offset = range.Offset; offset < End(range); offset += maxLength)
            {
                result.Add(range with { Offset = offset, Length = Math.Min(maxLength, End(range) - offset) });
            }
        }

        return result.ToImmutable();
    }

    private static int End(ReadItem item) => item.Offset + item.Length;

    /// <summary>
    /// Estimated cost with the k smallest gaps bridged, for every k: frames = the larger of the item bound and the
    /// capacity bound; blocks tracked as joined intervals (union-find) so the split count stays exact.
    /// </summary>
    private static long[] Estimate(List<ReadItem> ranges, int[] gaps, PollCostModel model, FrameCapacity capacity)
    {
        var parent = Enumerable.Range(0, ranges.Count).ToArray();
        var first = Enumerable.Range(0, ranges.Count).Select(i => ranges[i].Offset).ToArray();
        var end = ranges.Select(End).ToArray();
        var items = ranges.Sum(r => Pieces(r.Length, capacity.MaxBlockLength));
        var data = ranges.Sum(r => (long)r.Length);
        var estimates = new long[gaps.Length + 1];
        estimates[0] = Price(items, data);
        for (var k = 0; k < gaps.Length; k++)
        {
            int left = Root(parent, gaps[k]), right = Root(parent, gaps[k] + 1);
            items -= Pieces(end[left] - first[left], capacity.MaxBlockLength) + Pieces(end[right] - first[right], capacity.MaxBlockLength);
            data += first[right] - end[left];
            parent[right] = left;
            end[left] = end[right];
            items += Pieces(end[left] - first[left], capacity.MaxBlockLength);
            estimates[k + 1] = Price(items, data);
        }

        return estimates;

        long Price(long n, long d)
        {
            var frames = Math.Max(Ceiling(n, capacity.MaxItems), Ceiling((FrameCapacity.UnitsPerByte * d) + (FrameCapacity.UnitsPerItem * n), capacity.Units));
            return (frames * model.FrameCost(0, 0)) + (n * model.ItemChars) + (d * model.DataByteChars);
        }
    }

    private static int Pieces(int length, int maxLength) => (length + maxLength - 1) / maxLength;

    private static long Ceiling(long value, long divisor) => (value + divisor - 1) / divisor;

    private static int Root(int[] parent, int i)
    {
        while (parent[i] != i)
        {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }

        return i;
    }

    /// <summary>Joins range i with range i + 1 for every i in <paramref name="bridged"/>.</summary>
    private static List<ReadItem> Bridge(List<ReadItem> ranges, ReadOnlySpan<int> bridged)
    {
        var joined = new bool[ranges.Count];
        foreach (var i in bridged)
        {
            joined[i] = true;
        }

        var result = new List<ReadItem>();
        for (var i = 0; i < ranges.Count; i++)
        {
            if (i > 0 && joined[i - 1])
            {
                result[^1] = result[^1] with { Length = End(ranges[i]) - result[^1].Offset };
            }
            else
            {
                result.Add(ranges[i]);
            }
        }

        return result;
    }
}
