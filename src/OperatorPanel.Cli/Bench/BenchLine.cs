using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Cli.Bench;

/// <summary>A production line reduced to what the link cost depends on: one station, its CPU, and what the panel watches.</summary>
internal sealed record BenchLine(Station Station, CpuProfile Cpu, ImmutableArray<BenchTag> Tags)
{
    public IEnumerable<WatchedItem> WatchedItems => Tags.Select(t => new WatchedItem(Station, t.Address));

    /// <summary>
    /// The bytes that hold the watched data, each counted once: a bit costs its whole byte, eight alarm bits in one byte
    /// cost that byte once. No protocol that reads bytes can carry less, so this is the lower bound's data.
    /// </summary>
    public int DistinctDataBytes =>
        Tags.SelectMany(t => Enumerable.Range(t.Address.ByteOffset, t.Address.LastByte - t.Address.ByteOffset + 1)
            .Select(offset => (t.Address.Area, offset))).Distinct().Count();

    /// <summary>The poll plan the panel itself would use: the real planner, with the station's CPU known.</summary>
    public PollPlan Plan() => PollPlanner.Build(WatchedItems, new Dictionary<Station, CpuProfile> { [Station] = Cpu });
}
