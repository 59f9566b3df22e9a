using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// How the PC lays a station's list out (docs/protocol.md section 2, 05 DEFINE LIST): each range in order is cut into
/// items of at most 4 bytes, whose bytes follow one another in the list data; the last group of 8 slots is filled
/// with 1-byte items of SMB6 (the CPU's type, readable on every S7-200), which the data carries too. <see cref="Places"/>
/// says where each range starts in the data. False from <see cref="TryMake"/> when the ranges need more slots than the
/// handler has (or none).
/// </summary>
public sealed record ListPlan(ImmutableArray<ReadItem> Items, int DataBytes, ImmutableArray<int> Places)
{
    /// <summary>The byte a filler item reads: SMB6.</summary>
    public static readonly ReadItem Filler = new(ProtocolArea.SM, 6, 1);

    public static bool TryMake(IEnumerable<ReadItem> ranges, HandlerShape shape, out ListPlan plan)
    {
        ArgumentNullException.ThrowIfNull(ranges);
        ArgumentNullException.ThrowIfNull(shape);
        var items = ImmutableArray.CreateBuilder<ReadItem>();
        var places = ImmutableArray.CreateBuilder<int>();
        var place = 0;
        foreach (var range in ranges)
        {
            places.Add(place);
            for (var at = 0; at < range.Length; at += HandlerShape.ItemBytes)
            {
                var length = Math.Min(HandlerShape.ItemBytes, range.Length - at);
                items.Add(range with { Offset = range.Offset + at, Length = length });
                place += length;
            }
        }

        while (items.Count % HandlerShape.GroupSlots != 0)
        {
            items.Add(Filler);
            place++;
        }

        plan = new ListPlan(items.ToImmutable(), place, places.ToImmutable());
        return items.Count > 0 && items.Count <= shape.ListItems && place <= shape.ListBytes;
    }

    /// <summary>The one DEFINE LIST request for this plan.</summary>
    public Request Request(Addressing.Station station, byte sequence) => V3.Request.DefineList(station, sequence, Items);
}
