using System.Collections.Immutable;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The modeled part of `opanel bench link`: the line, its poll plan, the figures of every strategy, the one-time cost of
/// defining the READ lists, and the targets (evaluated on the steady-state refresh).
/// </summary>
internal sealed record LinkBenchReport(
    BenchLine Line,
    PollPlan Plan,
    ExchangeTiming Timing,
    ImmutableArray<TrafficFigures> Rows,
    TrafficFigures DefineLists,
    ImmutableArray<TargetResult> Targets)
{
    public static LinkBenchReport Create(BenchLine line, ExchangeTiming timing)
    {
        ArgumentNullException.ThrowIfNull(line);
        ArgumentNullException.ThrowIfNull(timing);
        var plan = line.Plan();
        var planned = TrafficModels.FromPlan(plan);
        var plain = TrafficModels.PlainReads(plan);
        var perItem = TrafficModels.OneItemPerRequest(line, plan.CostModel);
        var seed = TrafficModels.SeedOneItemPerRequest(line);
        var hex = TrafficModels.LowerBoundAsHex(line);
        var binary = TrafficModels.LowerBoundAsBinary(line);
        var targets = BenchTargets.Evaluate(planned, perItem, seed, hex, binary, timing);
        return new LinkBenchReport(line, plan, timing, [planned, plain, perItem, seed, hex, binary], TrafficModels.DefineListsOnce(plan), targets);
    }
}
