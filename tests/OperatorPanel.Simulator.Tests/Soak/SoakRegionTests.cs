using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Simulator.Soak;

namespace OperatorPanel.Simulator.Tests.Soak;

public sealed class SoakRegionTests
{
    private static readonly CpuProfile Cpu = CpuProfiles.For(CpuModel.Cpu226);

    /// <summary>VB9634: where the generator puts the full v3 handler on a CPU 226 (HandlerShape.Full.DefaultVFirst).</summary>
    private static readonly int HandlerFirst = HandlerShape.Full.DefaultVFirst(10240);

    [Fact]
    public void AreaEnds_Cpu226_WatchesEveryWidthAtTheEndOfIQMAndBelowTheHandler()
    {
        var region = SoakRegion.AreaEnds(Cpu, HandlerFirst);

        HandlerFirst.Should().Be(9634);
        region.ToString().Should().Be(
            "VD1000 VD1004 VD9630 VW9632 VB9633 V9633.0 QW14 QB15 Q15.7 MD20 MB29 MW30 M31.7 IB15 I15.0",
            "the handler serves no SM (docs/protocol.md section 1.3)");
    }

    [Fact]
    public void Written_AreaEnds_IsTheQMAndVItemsUpToTheLastByteBelowTheHandler()
    {
        var written = SoakRegion.AreaEnds(Cpu, HandlerFirst).Written;

        written.Select(a => a.Area).Distinct().Should().BeEquivalentTo([MemoryArea.V, MemoryArea.Q, MemoryArea.M]);
        written.Max(a => a.Area == MemoryArea.V ? a.LastByte : 0).Should().Be(HandlerFirst - 1);
        written.Should().Contain([PlcAddress.Parse("QW14"), PlcAddress.Parse("Q15.7"), PlcAddress.Parse("MW30"), PlcAddress.Parse("M31.7")]);
        written.Select(a => HandlerProtection.Refusal(a, Cpu)).Should().AllSatisfy(r => r.Should().BeNull());
    }

    /// <summary>
    /// What the panel's list holds for the region (the plan's frames in order, as V3StationList lays them out): one list of
    /// 8 slots, the ranges at the ends of Q, M and I each widened backward to the area's last 4 bytes, one of them
    /// behind another range of its frame.
    /// </summary>
    [Fact]
    public void AreaEnds_Cpu226_OneListWhoseRangesAtTheEndsOfQMAndIAreWidened()
    {
        var region = SoakRegion.AreaEnds(Cpu, HandlerFirst);
        var station = new Station(2);
        var plan = PollPlanner.Build(region.Items.Select(a => new WatchedItem(station, a)), new Dictionary<Station, CpuProfile> { [station] = Cpu });

        var fits = ListPlan.TryMake(plan.Frames.SelectMany(f => f.Items), HandlerShape.Full, ListPlan.AreaBytesOf(Cpu), out var list);

        plan.Rejected.Should().BeEmpty();
        plan.Frames.Should().Contain(f => f.Items.Contains(new ReadItem(ProtocolArea.M, 20, 4)) && f.Items.Contains(new ReadItem(ProtocolArea.M, 29, 3)),
            "MD20 and the widened MB29-MB31 share a frame, as the ranges did when MW30 was shown with the wrong bytes");
        fits.Should().BeTrue();
        list.Items.Should().HaveCount(HandlerShape.GroupSlots);
        list.Items.Should().Contain(
        [
            new ReadItem(ProtocolArea.Q, 12, 4), new ReadItem(ProtocolArea.M, 28, 4), new ReadItem(ProtocolArea.I, 12, 4),
            new ReadItem(ProtocolArea.M, 20, 4), new ReadItem(ProtocolArea.V, 9630, 4),
        ]);
    }
}
