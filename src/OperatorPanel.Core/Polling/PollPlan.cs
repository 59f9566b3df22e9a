using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The READ exchanges of one poll cycle, built by <see cref="PollPlanner.Build"/>: frames ordered by station, then by
/// their first item; every accepted watched item with the reply bytes that carry it; and the items left out.
/// </summary>
public sealed record PollPlan(
    ImmutableArray<PollFrame> Frames,
    ImmutableArray<PlannedValue> Values,
    ImmutableArray<PlanRejection> Rejected,
    ImmutableDictionary<Station, CpuProfile> Cpus,
    PollCostModel CostModel)
{
    public static PollPlan Empty { get; } = new([], [], [], ImmutableDictionary<Station, CpuProfile>.Empty, PollCostModel.Default);

    public int FrameCount => Frames.Length;

    /// <summary>Characters the PC sends per cycle.</summary>
    public int RequestChars => Frames.Sum(f => CostModel.RequestChars(f.Items.Length));

    /// <summary>Characters the stations send back per cycle (data included).</summary>
    public int ReplyChars => Frames.Sum(f => CostModel.ReplyChars(f.DataBytes));

    /// <summary>Data bytes read per cycle, merged gaps included.</summary>
    public int DataBytes => Frames.Sum(f => f.DataBytes);

    /// <summary>Requests, replies and per-frame turnaround in character times: what the planner minimised.</summary>
    public int CostChars => Frames.Sum(f => CostModel.FrameCost(f.Items.Length, f.DataBytes));

    public IEnumerable<Station> Stations => Frames.Select(f => f.Station).Distinct();
}
