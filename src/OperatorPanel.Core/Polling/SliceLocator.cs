using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// Finds the reply bytes that carry a span. Built once per plan: every item of every frame, per station, sorted by area
/// and offset (a station's items never overlap), so a span is found by binary search instead of a scan of all frames.
/// </summary>
internal sealed class SliceLocator
{
    private readonly Dictionary<Station, Placed[]> _items;

    public SliceLocator(ImmutableArray<PollFrame> frames)
    {
        var placed = new Dictionary<Station, List<Placed>>();
        for (var f = 0; f < frames.Length; f++)
        {
            if (!placed.TryGetValue(frames[f].Station, out var list))
            {
                list = [];
                placed[frames[f].Station] = list;
            }

            var dataOffset = 0;
            foreach (var item in frames[f].Items)
            {
                list.Add(new Placed(item, f, dataOffset));
                dataOffset += item.Length;
            }
        }

        _items = placed.ToDictionary(p => p.Key, p => p.Value.OrderBy(i => i.Item.Area).ThenBy(i => i.Item.Offset).ToArray());
    }

    /// <summary>The slices that carry <paramref name="span"/>, in address order; neighbours in one reply joined.</summary>
    public ImmutableArray<ReplySlice> Locate(Station station, ReadItem span)
    {
        var items = _items.GetValueOrDefault(station) ?? [];
        var index = FirstEndingAfter(items, span.Area, span.Offset);
        var slices = ImmutableArray.CreateBuilder<ReplySlice>();
        var address = span.Offset;
        var end = span.Offset + span.Length;
        while (address < end)
        {
            if (index >= items.Length || items[index].Item.Area != span.Area || items[index].Item.Offset > address)
            {
                throw new InvalidOperationException($"{station} {span.Area} byte {address} is in no frame of the plan");
            }

            var placed = items[index];
            var length = Math.Min(end, placed.Item.Offset + placed.Item.Length) - address;
            var slice = new ReplySlice(placed.Frame, placed.DataOffset + address - placed.Item.Offset, length);
            if (slices.Count > 0 && slices[^1].FrameIndex == slice.FrameIndex && slices[^1].DataOffset + slices[^1].Length == slice.DataOffset)
            {
                slices[^1] = slices[^1] with { Length = slices[^1].Length + length };
            }
            else
            {
                slices.Add(slice);
            }

            address += length;
            index++;
        }

        return slices.ToImmutable();
    }

    /// <summary>Index of the first item of <paramref name="area"/> that ends after <paramref name="address"/> (or of a later area).</summary>
    private static int FirstEndingAfter(Placed[] items, ProtocolArea area, int address)
    {
        int low = 0, high = items.Length;
        while (low < high)
        {
            var mid = (low + high) / 2;
            var item = items[mid].Item;
            if (item.Area < area || (item.Area == area && item.Offset + item.Length <= address))
            {
                low = mid + 1;
            }
            else
            {
                high = mid;
            }
        }

        return low;
    }

    private readonly record struct Placed(ReadItem Item, int Frame, int DataOffset);
}
