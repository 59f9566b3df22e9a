using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class ReferenceLineTests
{
    private static readonly BenchLine Line = ReferenceLine.Create();

    private static IEnumerable<PlcAddress> Memory =>
        Line.Tags.Where(t => t.Group is not ("inputs" or "outputs" or "alarms")).Select(t => t.Address);

    [Fact]
    public void Create_Cpu226AtStation2_WithAllLocalIoAsBytes()
    {
        Line.Cpu.Should().Be(CpuProfiles.For(CpuModel.Cpu226, CpuRevision.Current));
        Line.Station.Address.Should().Be(2);
        Line.Tags.Where(t => t.Group == "inputs").Select(t => t.Address.ToString()).Should().Equal("IB0", "IB1", "IB2");
        Line.Tags.Where(t => t.Group == "outputs").Select(t => t.Address.ToString()).Should().Equal("QB0", "QB1");
    }

    [Fact]
    public void Create_MemoryTags_ThirtyTwoInEvenWidthsScatteredOverVAndM()
    {
        Memory.Should().HaveCount(32).And.OnlyHaveUniqueItems();
        Memory.GroupBy(a => a.Width).Should().HaveCount(4).And.OnlyContain(g => g.Count() == 8);
        Memory.Count(a => a.Area == MemoryArea.V).Should().Be(24);
        Memory.Where(a => a.Area == MemoryArea.M).Should().HaveCount(8).And.OnlyContain(a => a.LastByte <= 9);
    }

    [Fact]
    public void Create_Alarms_SixtyFourBitsM10ToM17()
    {
        var alarms = Line.Tags.Where(t => t.Group == "alarms").Select(t => t.Address).ToList();

        alarms.Should().HaveCount(64).And.OnlyHaveUniqueItems().And.OnlyContain(a => a.Area == MemoryArea.M && a.Width == AccessWidth.Bit);
        alarms[0].ToString().Should().Be("M10.0");
        alarms[^1].ToString().Should().Be("M17.7");
    }

    [Fact]
    public void Plan_ReferenceLine_AcceptsEveryItemOnTheCpu()
    {
        var plan = Line.Plan();

        plan.Rejected.Should().BeEmpty();
        plan.Values.Should().HaveCount(101);
        Line.DistinctDataBytes.Should().Be(74, "IB0-2, QB0-1, MB0-MB17 and 51 V bytes");
    }

    [Fact]
    public void Plan_ReferenceLine_EveryFrameWithinTheReadRule()
    {
        var plan = Line.Plan();

        plan.Frames.Should().NotBeEmpty().And.OnlyContain(f => f.DataBytes <= ProtocolLimits.MaxReadDataFor(f.Items.Length));
        plan.Frames.Sum(f => f.DataBytes).Should().BeGreaterThanOrEqualTo(74);
    }
}
