using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The plan of a PPI bus: per station <see cref="PpiReadPlanner"/> merges the watched bytes into S7 items and packs them
/// into jobs (docs/ppi.md section 8); each item becomes one poll frame of one block, in job order, so a per-item return
/// code touches only the values that item carries, and Readers/PpiReader packs the frames back into the same jobs. Only
/// I, Q, M, V and SM are watched, as on a Freeport bus (the values' path carries those areas).
/// </summary>
public static class PpiPollPlanner
{
    public static PollPlan Build(IEnumerable<WatchedItem> items, IReadOnlyDictionary<Station, CpuProfile>? cpus = null)
    {
        ArgumentNullException.ThrowIfNull(items);
        var cpuMap = cpus?.ToImmutableDictionary() ?? ImmutableDictionary<Station, CpuProfile>.Empty;
        var frames = ImmutableArray.CreateBuilder<PollFrame>();
        var values = ImmutableArray.CreateBuilder<PlannedValue>();
        var rejected = ImmutableArray.CreateBuilder<PlanRejection>();
        foreach (var station in items.Distinct().GroupBy(i => i.Station).OrderBy(g => g.Key.Address))
        {
            var accepted = new List<WatchedItem>();
            foreach (var item in station)
            {
                if (RejectionReason(item, cpuMap) is { } reason)
                {
                    rejected.Add(new PlanRejection(item, reason));
                }
                else
                {
                    accepted.Add(item);
                }
            }

            var plan = PpiReadPlanner.Plan(accepted.Select(i => i.Address));
            var first = frames.Count;
            var firstOfRequest = new List<int>();
            foreach (var request in plan.Requests)
            {
                firstOfRequest.Add(frames.Count - first);
                frames.AddRange(request.Items.Select(item => new PollFrame(station.Key, [BlockOf(item)])));
            }

            foreach (var item in accepted.OrderBy(i => i.Address.Area).ThenBy(i => i.Address.ByteOffset).ThenBy(i => i.Address.Bit))
            {
                if (plan.Rejected.TryGetValue(item.Address, out var reason))
                {
                    rejected.Add(new PlanRejection(item, reason));
                    continue;
                }

                var slice = plan.Slices[item.Address];
                values.Add(new PlannedValue(item, [new ReplySlice(first + firstOfRequest[slice.Request] + slice.Item, slice.Offset, slice.Length)]));
            }
        }

        return new PollPlan(frames.ToImmutable(), values.ToImmutable(), rejected.ToImmutable(), cpuMap, PollCostModel.Default);
    }

    /// <summary>The bytes an S7 item of I, Q, M, V or SM covers, as a block of a poll frame.</summary>
    private static ReadItem BlockOf(Ppi.S7.S7Item item)
    {
        var area = Enum.GetValues<ProtocolArea>().First(a => PpiAddressing.TryArea(a.ToMemoryArea(), out var code) && code == item.Area);
        return new ReadItem(area, item.ByteOffset, item.DataLength);
    }

    private static string? RejectionReason(WatchedItem item, ImmutableDictionary<Station, CpuProfile> cpus)
    {
        if (ProtocolAreaExtensions.FromMemoryArea(item.Address.Area) is null)
        {
            return $"{item.Address}: the panel reads only I, Q, M, V and SM, over PPI as over Freeport";
        }

        return cpus.TryGetValue(item.Station, out var cpu) ? AddressRules.Check(item.Address, cpu)?.Message : null;
    }
}
