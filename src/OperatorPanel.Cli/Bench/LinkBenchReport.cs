using System.Collections.Immutable;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The modelled part of `opanel bench link`: the line, its poll plan, the characters of every strategy, the one-time
/// cost of defining the lists, the time model of the steady and idle refresh on the chosen medium, and the targets.
/// </summary>
internal sealed record LinkBenchReport(
    BenchLine Line,
    PollPlan Plan,
    ImmutableArray<TrafficFigures> Rows,
    TrafficFigures DefineLists,
    LinkTimeReport Time,
    ImmutableArray<string> HandlerProblems,
    ImmutableArray<TargetResult> Targets)
{
    public static LinkBenchReport Create(BenchLine line, LinkTimeModel model)
    {
        ArgumentNullException.ThrowIfNull(line);
        ArgumentNullException.ThrowIfNull(model);
        var plan = line.Plan();
        var cycles = RefreshCycles.For(plan);
        HandlerProbe.TryCreate(
            line.Cpu, line.Station, model.Line.Settings, (int)model.ReplyDelayMs, TimeSpan.FromMilliseconds(model.ProgramScanMs), out var probe, out var probeError);
        var handler = HandlerCosts.Measure(cycles, model, probe, probeError);
        var medium = model.Radio is null ? "PC/PPI cable" : "radio modules";
        var time = LinkTimeReport.Create(medium, model, cycles, handler, line);
        var planned = TrafficModels.FromCycle(TrafficModels.Planned, cycles.Steady);
        var perItem = TrafficModels.OneItemPerRequest(line);
        var seed = TrafficModels.SeedOneItemPerRequest(line);
        var rows = ImmutableArray.Create(
            planned,
            TrafficModels.FromCycle(TrafficModels.Idle, cycles.Idle),
            TrafficModels.PlainReads(plan),
            perItem,
            seed,
            TrafficModels.LowerBoundAsHex(line),
            TrafficModels.LowerBoundAsBinary(line));
        return new LinkBenchReport(
            line, plan, rows, TrafficModels.FromCycle(TrafficModels.DefineLists, cycles.Setup), time, handler.Problems, BenchTargets.Evaluate(planned, perItem, seed, time));
    }
}
