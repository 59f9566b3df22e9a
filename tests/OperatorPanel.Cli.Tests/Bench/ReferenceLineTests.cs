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
    public void Plan_ReferenceLine_TwoFramesWithinTheReadRuleAndTheFewestCharacters()
    {
        // 26 byte ranges weigh D + 2N = 74 + 52 = 126 > 121 (2D + 4N <= 243), and bridging never lowers that: two frames.
        // Bridging the four gaps under 4 bytes (2, 2, 2, 3) leaves 22 items and 83 bytes, the fewest characters any plan
        // can have: 2 x (12 + 12) + 8 x 22 + 2 x 83 = 390.
        var plan = Line.Plan();

        plan.Frames.Select(f => (f.Items.Length, f.DataBytes)).Should().Equal((20, 81), (2, 2));
        plan.Frames.Should().OnlyContain(f => f.DataBytes <= ProtocolLimits.MaxReadDataFor(f.Items.Length));
        (plan.RequestChars + plan.ReplyChars).Should().Be(390);
    }

    [Fact]
    public void FromPlan_ReferenceLine_FirstFrameIsAListTheSecondAPlainRead()
    {
        // Both lists would need a tail of 4 x 22 = 88 bytes plus the 174-character reply of frame 1: 262 > 255. Frame 1
        // alone: 80 + 174 = 254; frame 2 as a plain READ (28 characters, 2 descriptors, 16-character reply) keeps it.
        var plan = Line.Plan();

        ReadListAssignment.For(plan).Should().Equal(new Dictionary<int, int> { [0] = 1 });
        TrafficModels.FromPlan(plan).Should().Be(new TrafficFigures(TrafficModels.Planned, 2, 12 + 28, 190));
        TrafficModels.DefineListsOnce(plan).Should().Be(new TrafficFigures(TrafficModels.DefineLists, 1, 14 + 160, 12));
    }
}
