using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// Fills up to four stored lists of one station from its blocks, longest block first, within a bus-wide budget of
/// tail bytes (docs/protocol-v2.md, "Lists"): the blocks that do not fit stay for plain READs.
/// </summary>
internal static class ListFiller
{
    /// <summary>
    /// Lists in definition order (most items first: each list's descriptors are converted below the floor the earlier
    /// ones left, so the big list goes where the room is) and the blocks left over, in the order given. A list obeys
    /// <see cref="ProtocolLimits.ListsFit"/>; all lists together take at most <paramref name="tailBytes"/> bytes, and
    /// every list's longest reply ends below 256 - <paramref name="tailBytes"/>, the floor every station on the bus keeps
    /// clear. On a shared bus the DEFINE LIST request must end below that floor too: it reaches the other stations'
    /// buffers, and a define that wiped another station's lists every time that station redefined its own would never settle.
    /// </summary>
    public static (List<ImmutableArray<ReadItem>> Lists, List<ReadItem> Remaining) Fill(
        IEnumerable<ReadItem> blocksLongestFirst, int tailBytes, bool sharedBus, PollCostModel model)
    {
        var lists = new List<OpenList>();
        var rest = new List<ReadItem>();
        var itemBudget = tailBytes / 4;
        var lastFree = ProtocolLimits.MaxFrameChars - tailBytes;
        foreach (var block in blocksLongestFirst)
        {
            var target = itemBudget > 0 ? lists.Find(l => Accepts(l, block)) : null;
            if (target is null && itemBudget > 0 && lists.Count < Math.Min(model.MaxListsPerStation, ProtocolLimits.MaxLists) && Accepts(new OpenList(), block))
            {
                target = new OpenList();
                lists.Add(target);
            }

            if (target is null)
            {
                rest.Add(block);
                continue;
            }

            target.Items.Add(block);
            target.DataBytes += block.Length;
            itemBudget--;
        }

        var ordered = lists.OrderByDescending(l => l.Items.Count).ToList();
        while (ordered.Count > 0 && !ProtocolLimits.ListsFit(ordered.Select(l => (l.Items.Count, l.DataBytes))))
        {
            // Rare: the ATH rule of a later list. Hand the fullest list's shortest block to plain READ and try again.
            var fullest = ordered[0];
            var shortest = fullest.Items[^1];
            fullest.Items.RemoveAt(fullest.Items.Count - 1);
            fullest.DataBytes -= shortest.Length;
            rest.Add(shortest);
            ordered = [.. ordered.Where(l => l.Items.Count > 0).OrderByDescending(l => l.Items.Count)];
        }

        return ([.. ordered.Select(l => ImmutableArray.Create(BlockOrder.Sorted(l.Items, BlockOrder.ByAddress)))], rest);

        bool Accepts(OpenList list, ReadItem block)
        {
            var items = list.Items.Count + 1;
            var data = list.DataBytes + block.Length;
            return items <= model.MaxItemsPerFrame
                && data <= model.MaxDataFor(items)
                && model.ListFullReplyChars(data) <= lastFree
                && (!sharedBus || model.DefineListRequestChars(items) <= lastFree);
        }
    }

    private sealed class OpenList
    {
        public List<ReadItem> Items { get; } = [];

        public int DataBytes { get; set; }
    }
}
