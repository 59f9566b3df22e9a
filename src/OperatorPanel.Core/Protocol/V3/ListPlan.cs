using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// How the PC lays a station's list out (docs/protocol.md section 2, 05 DEFINE LIST). Each range in order is cut into
/// items of at most 4 bytes whose bytes follow one another in the list data; the handler compares each slot's 4-byte
/// WINDOW (from the item's first byte) with its copy, so every window must lie inside its area. The pieces of a range
/// are cut from its end (4, 4, ... and the short piece first), so every window but a lone short range's lies inside the
/// range; a short range whose window would pass its area's end (by the area sizes given; without them nothing is
/// widened, and the handler refuses such an item with 82) is widened backward to a 4-byte item that ends at the range's end. The last group of 8 slots is filled with 1-byte
/// items of IB12 (<see cref="Filler"/>). <see cref="Places"/> says where each range's first byte
/// lies in the data, <see cref="Starts"/> where each item's. False from TryMake when the ranges need more
/// slots or bytes than the handler has (or none).
/// </summary>
public sealed record ListPlan(ImmutableArray<ReadItem> Items, int DataBytes, ImmutableArray<int> Places)
{
    /// <summary>
    /// The byte a filler item reads: IB12, its window IB12-IB15, the input image's last 4 bytes (IB0-IB15 on every
    /// S7-200: seed 002 Table 1-1, "Digital I/O image size 256 (128 In/128 Out)", docs/cpu-profiles.md), far from the
    /// local inputs; whether they change depends on the expansion modules fitted (not in a page found). Any byte the
    /// handler serves would do: the PC ignores a filler's data, and a window that changes only brings CHANGES entries
    /// the PC ignores. Not SMB6, as before:
    /// the handler no longer serves SM (docs/sources/s7200-facts.md section 13).
    /// </summary>
    public static readonly ReadItem Filler = new(ProtocolArea.I, 12, 1);

    /// <summary>Where each item's bytes start in the list data.</summary>
    public ImmutableArray<int> Starts { get; } = [.. Items.Select((item, k) => Items.Take(k).Sum(i => i.Length))];

    public static bool TryMake(IEnumerable<ReadItem> ranges, HandlerShape shape, out ListPlan plan) => TryMake(ranges, shape, null, out plan);

    /// <summary>The plan, widening a short range only when its window would pass the end of its area (<paramref name="areaBytes"/>'s bytes).</summary>
    public static bool TryMake(IEnumerable<ReadItem> ranges, HandlerShape shape, Func<ProtocolArea, int>? areaBytes, out ListPlan plan)
    {
        ArgumentNullException.ThrowIfNull(ranges);
        ArgumentNullException.ThrowIfNull(shape);
        const int window = HandlerShape.ItemBytes;
        var items = ImmutableArray.CreateBuilder<ReadItem>();
        var places = ImmutableArray.CreateBuilder<int>();
        var place = 0;
        foreach (var range in ranges)
        {
            if (range.Length < window && areaBytes is not null && range.Offset + window > areaBytes(range.Area) && range.Offset + range.Length >= window)
            {
                var widened = range with { Offset = range.Offset + range.Length - window, Length = window };
                places.Add(place + window - range.Length);
                items.Add(widened);
                place += window;
                continue;
            }

            places.Add(place);
            var first = range.Length % window == 0 ? window : range.Length % window;
            for (var at = 0; at < range.Length; at += at == 0 ? first : window)
            {
                var length = at == 0 ? first : window;
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

    /// <summary>The bytes of each area on <paramref name="cpu"/>, for <see cref="TryMake(IEnumerable{ReadItem}, HandlerShape, Func{ProtocolArea, int}?, out ListPlan)"/>.</summary>
    public static Func<ProtocolArea, int> AreaBytesOf(Cpu.CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return area => cpu.TryGetArea(area.ToMemoryArea(), out var range) ? range.ByteCount : 0;
    }

    /// <summary>The one DEFINE LIST request for this plan.</summary>
    public Request Request(Addressing.Station station, byte sequence) => V3.Request.DefineList(station, sequence, Items);
}
