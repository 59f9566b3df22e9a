using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// Turns watched items into READ frames. Per station and area the byte ranges are coalesced, then gaps are bridged
/// smallest first while that lowers the <see cref="PollCostModel"/> cost of the whole station (one item saves
/// 8 request characters and a frame saves its framing and turnaround; a gap byte costs 2 reply characters), ranges
/// longer than a one-item reply (119 bytes) are split, and the blocks are packed into frames of at most 20 items whose
/// data obeys the protocol's 2D + 4N &lt;= 243 rule (119 bytes with one item, 81 with twenty).
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

        var frames = ImmutableArray.CreateBuilder<PollFrame>();
        var capacity = model.PlainCapacity(0);
        foreach (var station in accepted.GroupBy(i => i.Station).OrderBy(g => g.Key.Address))
        {
            var blocks = RangeMerger.Cheapest(station.Select(Span), model, capacity);
            frames.AddRange(FramePacker.Pack(blocks, capacity).Select(f => new PollFrame(station.Key, f)));
        }

        var frameArray = frames.ToImmutable();
        var locator = new SliceLocator(frameArray);
        var values = accepted
            .OrderBy(i => i.Station.Address).ThenBy(i => i.Address.Area).ThenBy(i => i.Address.ByteOffset).ThenBy(i => i.Address.Bit)
            .Select(i => new PlannedValue(i, locator.Locate(i.Station, Span(i))))
            .ToImmutableArray();
        return new PollPlan(frameArray, values, rejected.ToImmutable(), cpuMap, model);
    }

    /// <summary>The bytes an item touches, as a one-item block.</summary>
    internal static ReadItem Span(WatchedItem item) =>
        new(ProtocolAreaExtensions.FromMemoryArea(item.Address.Area)!.Value, item.Address.ByteOffset, item.Address.LastByte - item.Address.ByteOffset + 1);

    private static string? RejectionReason(WatchedItem item, ImmutableDictionary<Station, CpuProfile> cpus)
    {
        if (ProtocolAreaExtensions.FromMemoryArea(item.Address.Area) is null)
        {
            return $"{item.Address}: the panel link reads only I, Q, M, V and SM";
        }

        return cpus.TryGetValue(item.Station, out var cpu) ? AddressRules.Check(item.Address, cpu)?.Message : null;
    }
}
