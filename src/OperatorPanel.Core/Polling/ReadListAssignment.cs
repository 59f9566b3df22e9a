using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>Which frames of a <see cref="PollPlan"/> are polled as READ lists, and under which list id (docs/protocol.md, "Lists").</summary>
public static class ReadListAssignment
{
    /// <summary>
    /// Frame index to list id (1-4). Per station, in frame order, a frame gets the next id while all the station's lists
    /// still fit the handler's buffer tail together (<see cref="ProtocolLimits.ListsFit"/>) and every frame left to
    /// plain READ keeps them intact (<see cref="ProtocolLimits.ReadKeepsLists"/>); the other frames use plain READ.
    /// </summary>
    public static ImmutableDictionary<int, int> For(PollPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        var ids = ImmutableDictionary.CreateBuilder<int, int>();
        foreach (var station in plan.Stations)
        {
            var frames = Enumerable.Range(0, plan.Frames.Length).Where(i => plan.Frames[i].Station == station).ToList();
            var lists = new List<int>();
            foreach (var candidate in frames)
            {
                var chosen = lists.Append(candidate).ToList();
                var tail = chosen.Sum(i => 4 * plan.Frames[i].Items.Length);
                if (ProtocolLimits.ListsFit(chosen.Select(i => (plan.Frames[i].Items.Length, plan.Frames[i].DataBytes)))
                    && frames.Except(chosen).All(i => ProtocolLimits.ReadKeepsLists(tail, plan.Frames[i].Items.Length, plan.Frames[i].DataBytes)))
                {
                    lists.Add(candidate);
                    ids.Add(candidate, lists.Count);
                }
            }
        }

        return ids.ToImmutable();
    }
}
