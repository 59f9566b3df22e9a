using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// Times <see cref="PollPlanner.Build"/>, the planner's public API, on <see cref="PlanBenchTags"/> for one CPU 226
/// station: one warm-up run, then <c>runs</c> timed runs; allocations counted on this thread (the planner runs on it).
/// </summary>
internal static class PlanBench
{
    public static readonly int[] DefaultSizes = [200, 2000, 20000];

    private static readonly Station Station = new(2);

    public static PlanTiming Time(int tags, int runs, TimeProvider time)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(runs, 1);
        ArgumentNullException.ThrowIfNull(time);
        var cpu = CpuProfiles.For(CpuModel.Cpu226, CpuRevision.Current);
        var items = PlanBenchTags.Create(tags, Station, cpu);
        var cpus = new Dictionary<Station, CpuProfile> { [Station] = cpu };
        var plan = PollPlanner.Build(items, cpus);
        var samples = new List<(double Ms, long Bytes)>(runs);
        for (var i = 0; i < runs; i++)
        {
            var allocated = GC.GetAllocatedBytesForCurrentThread();
            var started = time.GetTimestamp();
            plan = PollPlanner.Build(items, cpus);
            samples.Add((time.GetElapsedTime(started).TotalMilliseconds, GC.GetAllocatedBytesForCurrentThread() - allocated));
        }

        var sorted = samples.OrderBy(s => s.Ms).ToList();
        var median = sorted[sorted.Count / 2];
        return new PlanTiming(tags, runs, median.Ms, sorted[^1].Ms, median.Bytes, plan.FrameCount, plan.Values.Length, plan.Rejected.Length);
    }
}
