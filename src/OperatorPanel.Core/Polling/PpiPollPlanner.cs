using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The plan of a PPI bus: per station <see cref="PpiReadPlanner"/> merges the watched bytes into S7 items and packs them
/// into jobs (docs/ppi.md section 8); each item becomes one poll frame of one block, in job order, so a per-item return
/// code touches only the values that item carries, and Readers/PpiReader packs the frames back into the same jobs. The
/// frames carry the S7 items themselves (<see cref="PollFrame.PpiItem"/>), so every area PPI reads is watched: I, Q, M,
/// V, SM, S, AIW, AQW and timer and counter current values (<see cref="LinkAreas.Reads"/>).
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
                frames.AddRange(request.Items.Select(item => PollFrame.ForPpi(station.Key, item)));
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

    private static string? RejectionReason(WatchedItem item, ImmutableDictionary<Station, CpuProfile> cpus)
    {
        return LinkAreas.Refusal(item.Address, LinkProtocol.Ppi, cpus.GetValueOrDefault(item.Station));
    }
}
