using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>One station's frames for one tail budget: its stored lists (in id order) and its plain READs, and their price.</summary>
internal sealed record StationLayout(Station Station, List<ImmutableArray<ReadItem>> Lists, List<ImmutableArray<ReadItem>> Plain, long Cost)
{
    /// <summary>
    /// The cheaper of: lists filled from the blocks bridged for plain READs, the rest packed into plain READs that keep
    /// the lists intact; and (when the budget allows lists) every unbridged range in lists and no plain READ at all,
    /// since inside a list a gap byte costs a character every cycle while an item costs only tail room.
    /// </summary>
    public static StationLayout Best(StationBlocks blocks, int tailBytes, FrameCapacity plain, bool sharedBus, PollCostModel model)
    {
        var (lists, rest) = ListFiller.Fill(blocks.BridgedLongestFirst(plain.MaxBlockLength), tailBytes, sharedBus, model);
        var frames = rest.Count == 0 ? [] : FramePacker.Pack(rest, plain);
        var best = new StationLayout(blocks.Station, lists, frames, Price(lists, frames, model));
        if (tailBytes > 0)
        {
            var (allLists, left) = ListFiller.Fill(blocks.RangesLongestFirst(plain.MaxBlockLength), tailBytes, sharedBus, model);
            var cost = Price(allLists, [], model);
            if (left.Count == 0 && cost < best.Cost)
            {
                best = new StationLayout(blocks.Station, allLists, [], cost);
            }
        }

        return best;
    }

    private static long Price(List<ImmutableArray<ReadItem>> lists, List<ImmutableArray<ReadItem>> plain, PollCostModel model) =>
        lists.Sum(l => (long)model.ListFrameCost(DataBytes(l))) + plain.Sum(f => (long)model.FrameCost(f.Length, DataBytes(f)));

    private static int DataBytes(ImmutableArray<ReadItem> items)
    {
        var sum = 0;
        foreach (var item in items)
        {
            sum += item.Length;
        }

        return sum;
    }
}
