using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class PlanBenchTests
{
    private static readonly CpuProfile Cpu226 = CpuProfiles.For(CpuModel.Cpu226, CpuRevision.Current);

    [Fact]
    public void Create_TwoThousand_SameTagsEveryTimeInsideTheCpuAreas()
    {
        var tags = PlanBenchTags.Create(2000, new Station(2), Cpu226);

        tags.Should().HaveCount(2000).And.Equal(PlanBenchTags.Create(2000, new Station(2), Cpu226));
        tags.Where(t => !(Cpu226.TryGetArea(t.Address.Area, out var area) && t.Address.LastByte <= area.LastByte)).Should().BeEmpty();
        tags.Select(t => t.Address.Area).Distinct().Should().BeEquivalentTo([MemoryArea.I, MemoryArea.Q, MemoryArea.M, MemoryArea.V]);
        tags.Select(t => t.Address.Width).Distinct().Should().HaveCount(4);
    }

    [Fact]
    public void Time_TwoHundredTags_EveryTagPlannedOnce()
    {
        var timing = PlanBench.Time(200, 1, TimeProvider.System);

        timing.Tags.Should().Be(200);
        (timing.Values + timing.Rejected).Should().Be(PlanBenchTags.Create(200, new Station(2), Cpu226).Distinct().Count());
        timing.Frames.Should().BePositive();
    }
}
