using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The exchanges of one poll cycle, built by <see cref="PollPlanner.Build"/>: frames ordered by station, a station's
/// stored lists first (in list id order, the order they are defined in), then its plain READs by their first item;
/// every accepted watched item with the reply bytes that carry it; and the items left out.
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

    /// <summary>Frames stored as lists and polled with READ CHANGES.</summary>
    public int ListCount => Frames.Count(f => f.List is not null);

    /// <summary>Characters the PC sends per steady cycle: READ CHANGES for a list, READ with its descriptors otherwise.</summary>
    public int RequestChars => Frames.Sum(f => f.List is null ? CostModel.RequestChars(f.Items.Length) : CostModel.ReadChangesRequestChars);

    /// <summary>Characters the stations send back per full refresh: every list answering FULL, every READ its data.</summary>
    public int ReplyChars => Frames.Sum(f => f.List is null ? CostModel.ReplyChars(f.DataBytes) : CostModel.ListFullReplyChars(f.DataBytes));

    /// <summary>Both ways per steady cycle in which every byte changed (every list answers FULL).</summary>
    public int FullRefreshChars => RequestChars + ReplyChars;

    /// <summary>
    /// Both ways per steady cycle in which nothing changed: a station's lists cost one 09 READ CHANGES OF LISTS answered
    /// with K = 0 per list (14 + 18 + 2 x lists; a handler without FEATURES bit 2 costs 36 per list with 08), a plain READ
    /// its request and data.
    /// </summary>
    public int IdleChars =>
        Frames.Where(f => f.List is null).Sum(f => CostModel.RequestChars(f.Items.Length) + CostModel.ReplyChars(f.DataBytes))
        + Frames.Where(f => f.List is not null).GroupBy(f => f.Station)
            .Sum(lists => CostModel.ReadChangesOfListsRequestChars + CostModel.ListsIdleReplyChars(lists.Count()));

    /// <summary>The one-off DEFINE LIST exchanges (request and 18-character reply) before the first steady cycle.</summary>
    public int DefineChars => Frames.Where(f => f.List is not null)
        .Sum(f => CostModel.DefineListRequestChars(f.Items.Length) + CostModel.ReplyChars(0));

    /// <summary>Data bytes read per full refresh, merged gaps included.</summary>
    public int DataBytes => Frames.Sum(f => f.DataBytes);

    /// <summary>What the planner minimised: every exchange with its turnaround, a list's data at the list price (<see cref="PollCostModel.ListFrameCost"/>).</summary>
    public int CostChars => Frames.Sum(f => f.List is null ? CostModel.FrameCost(f.Items.Length, f.DataBytes) : CostModel.ListFrameCost(f.DataBytes));

    public IEnumerable<Station> Stations => Frames.Select(f => f.Station).Distinct();
}
