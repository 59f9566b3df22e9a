using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>Chooses which gaps between one station's byte ranges to read over, by the cost of the packed result.</summary>
internal static class RangeMerger
{
    /// <summary>
    /// Coalesces overlapping and touching spans, then tries bridging the k smallest gaps for every k and keeps the
    /// cheapest packed plan (on a tie, the one reading fewer bytes). Returned blocks are split to fit one reply.
    /// </summary>
    public static ImmutableArray<ReadItem> Cheapest(IEnumerable<ReadItem> spans, PollCostModel model)
    {
        var ranges = Coalesce(spans);
        var gaps = Enumerable.Range(0, ranges.Count - 1)
            .Where(i => ranges[i].Area == ranges[i + 1].Area)
            .OrderBy(i => ranges[i + 1].Offset - End(ranges[i])).ThenBy(i => ranges[i].Area).ThenBy(i => ranges[i].Offset)
            .ToList();
        ImmutableArray<ReadItem> best = default;
        var bestCost = int.MaxValue;
        for (var k = 0; k <= gaps.Count; k++)
        {
            var bridged = gaps.Take(k).ToHashSet();
            var blocks = Split(Bridge(ranges, bridged), model.MaxDataFor(1));
            var cost = FramePacker.Pack(blocks, model).Sum(f => model.FrameCost(f.Length, f.Sum(i => i.Length)));
            if (cost < bestCost)
            {
                best = blocks;
                bestCost = cost;
            }
        }

        return best;
    }

    private static int End(ReadItem item) => item.Offset + item.Length;

    private static List<ReadItem> Coalesce(IEnumerable<ReadItem> spans)
    {
        var result = new List<ReadItem>();
        foreach (var span in spans.OrderBy(s => s.Area).ThenBy(s => s.Offset))
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

    /// <summary>Joins range i with range i + 1 for every i in <paramref name="bridged"/>.</summary>
    private static List<ReadItem> Bridge(List<ReadItem> ranges, HashSet<int> bridged)
    {
        var result = new List<ReadItem>();
        for (var i = 0; i < ranges.Count; i++)
        {
            if (i > 0 && bridged.Contains(i - 1))
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

    /// <summary>Cuts ranges longer than a one-item reply into full-size pieces and a remainder.</summary>
    private static ImmutableArray<ReadItem> Split(List<ReadItem> ranges, int maxLength)
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
}
