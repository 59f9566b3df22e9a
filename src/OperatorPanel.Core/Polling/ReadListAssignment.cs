using System.Collections.Immutable;

namespace OperatorPanel.Core.Polling;

/// <summary>Which frames of a <see cref="PollPlan"/> are polled as stored lists, and under which list id (docs/protocol-v2.md, "Lists").</summary>
public static class ReadListAssignment
{
    /// <summary>Frame index to list id (1-4), as the planner chose them (<see cref="PollFrame.List"/>).</summary>
    public static ImmutableDictionary<int, int> For(PollPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        return Enumerable.Range(0, plan.Frames.Length)
            .Where(i => plan.Frames[i].List is not null)
            .ToImmutableDictionary(i => i, i => plan.Frames[i].List!.Value);
    }
}
