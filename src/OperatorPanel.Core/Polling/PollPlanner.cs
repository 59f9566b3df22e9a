using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// Turns watched items into the exchanges of a poll cycle: stored lists (DEFINE LIST once, then READ CHANGES) and plain
/// READs. Per station the byte ranges are coalesced and the gaps worth reading over for plain READs are chosen
/// (<see cref="RangeMerger"/>: an item costs 8 request characters, a gap byte 2 reply characters, a frame its framing and
/// turnaround). Then, for a tail budget T shared by the bus, each station fills up to four lists, longest blocks first
/// (<see cref="ListFiller"/>), and packs the rest into plain READs that keep the lists intact (<see cref="FramePacker"/>,
/// <see cref="ProtocolLimits.ReadKeepsLists"/>); a station whose unbridged ranges all fit in lists reads nothing else.
/// The T with the lowest <see cref="PollCostModel"/> price wins. Every step is a sort or a sweep over the blocks:
/// planning 2000 tags takes milliseconds, not seconds.
/// </summary>
public static class PollPlanner
{
    public static PollPlan Build(
        IEnumerable<WatchedItem> items,
        IReadOnlyDictionary<Station, CpuProfile>? cpus = null,
        PollCostModel? costModel = null)
    {
        ArgumentNullException.ThrowIfNull(items);
        var model = costModel ?? PollCostModel.Default;
        var cpuMap = cpus?.ToImmutableDictionary() ?? ImmutableDictionary<Station, CpuProfile>.Empty;
        var accepted = new List<WatchedItem>();
        var rejected = ImmutableArray.CreateBuilder<PlanRejection>();
        foreach (var item in items.Distinct())
        {
            var reason = RejectionReason(item, cpuMap);
            if (reason is null)
            {
                accepted.Add(item);
            }
            else
            {
                rejected.Add(new PlanRejection(item, reason));
            }
        }

        var stations = accepted.GroupBy(i => i.Station).OrderBy(g => g.Key.Address)
            .Select(g => StationBlocks.Of(g.Key, g.Select(Span), model))
            .ToList();
        var frameArray = Frames(Cheapest(stations, model)).ToImmutableArray();
        var locator = new SliceLocator(frameArray);
        var values = accepted
            .OrderBy(i => i.Station.Address).ThenBy(i => i.Address.Area).ThenBy(i => i.Address.ByteOffset).ThenBy(i => i.Address.Bit)
            .Select(i => new PlannedValue(i, locator.Locate(i.Station, Span(i))))
            .ToImmutableArray();
        return new PollPlan(frameArray, values, rejected.ToImmutable(), cpuMap, model);
    }

    /// <summary>
    /// The cheapest layouts of all stations for one tail budget T shared by the bus (every frame on an RS-485 bus lands
    /// in every station's buffer, so all keep the same floor 256 - T clear). T is searched coarsely (steps of
    /// <see cref="CoarseStep"/> bytes), then in 4-byte steps around the best; a tie keeps the smaller tail.
    /// </summary>
    private static List<StationLayout> Cheapest(List<StationBlocks> stations, PollCostModel model)
    {
        var sharedBus = stations.Count > 1;
        var tried = new Dictionary<int, (long Cost, List<StationLayout> Layouts)>();
        for (var tail = 0; Try(tail) && model.MaxListsPerStation > 0; tail += CoarseStep)
        {
        }

        var coarse = tried.MinBy(t => (t.Value.Cost, t.Key)).Key;
        for (var tail = Math.Max(4, coarse - CoarseStep + 4); tail < coarse + CoarseStep && model.MaxListsPerStation > 0; tail += 4)
        {
            Try(tail);
        }

        return tried.MinBy(t => (t.Value.Cost, t.Key)).Value.Layouts;

        // False once a plain READ no longer fits under the tail: larger budgets only get worse.
        bool Try(int tail)
        {
            if (tried.ContainsKey(tail))
            {
                return true;
            }

            var plain = model.PlainCapacity(tail);
            if (!plain.Usable)
            {
                return false;
            }

            var layouts = stations.Select(s => StationLayout.Best(s, tail, plain, sharedBus, model)).ToList();
            tried[tail] = (layouts.Sum(l => l.Cost), layouts);
            return true;
        }
    }

    private static IEnumerable<PollFrame> Frames(List<StationLayout> layouts) => layouts.SelectMany(l =>
        l.Lists.Select((items, i) => new PollFrame(l.Station, items) { List = i + 1 })
            .Concat(l.Plain.Select(items => new PollFrame(l.Station, items))));

    /// <summary>Tail bytes between coarse tries: four list items.</summary>
    private const int CoarseStep = 16;

    /// <summary>The bytes an item touches, as a one-item block.</summary>
    internal static ReadItem Span(WatchedItem item) =>
        new(ProtocolAreaExtensions.FromMemoryArea(item.Address.Area)!.Value, item.Address.ByteOffset, item.Address.LastByte - item.Address.ByteOffset + 1);

    private static string? RejectionReason(WatchedItem item, ImmutableDictionary<Station, CpuProfile> cpus)
    {
        if (LinkAreas.ReadRefusal(item.Address, LinkProtocol.Freeport) is { } notServed)
        {
            return notServed;
        }

        return cpus.TryGetValue(item.Station, out var cpu) ? AddressRules.Check(item.Address, cpu)?.Message : null;
    }
}
