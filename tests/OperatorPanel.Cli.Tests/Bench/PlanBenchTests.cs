using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class PlanBenchTests
{
    private static readonly CpuProfile Cpu226 = CpuProfiles.For(CpuModel.Cpu226, CpuRevision.Current);

    [Fact]
    public void Create_TwentyThousand_DistinctSameEveryTimeInsideTheCpuAreas()
    {
        var tags = PlanBenchTags.Create(20000, new Station(2), Cpu226);

        tags.Should().HaveCount(20000).And.OnlyHaveUniqueItems().And.Equal(PlanBenchTags.Create(20000, new Station(2), Cpu226));
        tags.Where(t => !(Cpu226.TryGetArea(t.Address.Area, out var area) && t.Address.LastByte <= area.LastByte)).Should().BeEmpty();
        tags.Select(t => t.Address.Area).Distinct().Should().BeEquivalentTo([MemoryArea.I, MemoryArea.Q, MemoryArea.M, MemoryArea.V]);
        tags.Select(t => t.Address.Width).Distinct().Should().HaveCount(4);
    }

    [Fact]
    public void Time_TwoHundredTags_EveryTagPlannedOnce()
    {
        var timing = PlanBench.Time(200, 1, TimeProvider.System);

        timing.Tags.Should().Be(200);
        (timing.Values + timing.Rejected).Should().Be(200);
        timing.Frames.Should().BePositive();
    }
}
