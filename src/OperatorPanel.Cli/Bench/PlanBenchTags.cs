using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// Watched items for the planner benchmark, one station, deterministic (fixed seed): scattered the way programs scatter
/// them, in clusters (a recipe block, an alarm word, a block of counters) over the CPU's whole I, Q, M and V areas:
/// 5% input bits, 5% output bits, 10% M bits and bytes, 80% V (40% bits, 20% bytes, 30% words, 10% double words).
/// Every tag is a different address (the planner would merge repeats): when the small areas are full (I and Q have
/// 128 bits each on a CPU 226), the repeats drawn there are drawn again, so large counts lean further towards V.
/// </summary>
internal static class PlanBenchTags
{
    private const int Seed = 2026;
    private const int ClusterBytes = 48;
    private const int TagsPerCluster = 12;

    public static List<WatchedItem> Create(int count, Station station, CpuProfile cpu)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(count);
        ArgumentNullException.ThrowIfNull(cpu);
        var random = new Random(Seed);
        var items = new List<WatchedItem>(count);
        var seen = new HashSet<PlcAddress>();
        var cluster = (Area: MemoryArea.V, Base: 0);
        for (var i = 0; items.Count < count; i++)
        {
            var (area, width) = Draw(random.Next(100), random.Next(100));
            cpu.TryGetArea(area, out var range);
            if (i % TagsPerCluster == 0 || cluster.Area != area)
            {
                cluster = (area, random.Next(Math.Max(1, range.ByteCount - ClusterBytes)));
            }

            var last = range.ByteCount - width.ByteCount();
            var offset = Math.Min(last, cluster.Base + random.Next(Math.Min(ClusterBytes, range.ByteCount)));
            var address = width == AccessWidth.Bit ? PlcAddress.ForBit(area, offset, random.Next(8)) : PlcAddress.ForBytes(area, offset, width);
            if (seen.Add(address))
            {
                items.Add(new WatchedItem(station, address));
            }
        }

        return items;
    }

    /// <summary>The area by <paramref name="areaRoll"/> (percent), the width within it by <paramref name="widthRoll"/>.</summary>
    private static (MemoryArea Area, AccessWidth Width) Draw(int areaRoll, int widthRoll) => areaRoll switch
    {
        < 5 => (MemoryArea.I, AccessWidth.Bit),
        < 10 => (MemoryArea.Q, AccessWidth.Bit),
        < 20 => (MemoryArea.M, widthRoll < 70 ? AccessWidth.Bit : AccessWidth.Byte),
        _ => (MemoryArea.V, widthRoll < 40 ? AccessWidth.Bit : widthRoll < 60 ? AccessWidth.Byte : widthRoll < 90 ? AccessWidth.Word : AccessWidth.DoubleWord),
    };
}
