using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>A PPI bus's plan: one poll frame per S7 item of PpiReadPlanner, each value's slice in its item.</summary>
public sealed class PpiPollPlannerTests
{
    private static readonly Station Cpu2 = new(2);

    [Fact]
    public void Build_MergedRangesPerArea_OneFramePerItemAndSlicesInThem()
    {
        var plan = PpiPollPlanner.Build(Items("VB100", "VW102", "M0.3", "MB1", "VB200"));

        plan.Frames.Select(f => f.Items.Single()).Should().Equal(
            new ReadItem(ProtocolArea.M, 0, 2), new ReadItem(ProtocolArea.V, 100, 4), new ReadItem(ProtocolArea.V, 200, 1));
        Slice(plan, "VW102").Should().Be(new ReplySlice(1, 2, 2));
        Slice(plan, "M0.3").Should().Be(new ReplySlice(0, 0, 1));
        Slice(plan, "VB200").Should().Be(new ReplySlice(2, 0, 1));
    }

    [Fact]
    public void Build_AddressBeyondTheCpuOrNotOnTheValuesPath_RejectedWithTheReason()
    {
        var plan = PpiPollPlanner.Build(Items("VB100", "VB9000", "AIW0"), new Dictionary<Station, CpuProfile> { [Cpu2] = CpuProfiles.For(CpuModel.Cpu221) });

        plan.Rejected.Select(r => r.Item.Address.ToString()).Should().BeEquivalentTo(["VB9000", "AIW0"]);
        plan.Rejected.Single(r => r.Item.Address.Area == MemoryArea.AI).Reason.Should().Contain("I, Q, M, V and SM");
        plan.Frames.Should().ContainSingle();
    }

    [Fact]
    public void Build_TwoStations_FramesInStationOrderEachOwnJobs()
    {
        var items = Items("VB0").Concat([new WatchedItem(new Station(3), PlcAddress.Parse("VB0"))]);

        var plan = PpiPollPlanner.Build(items);

        plan.Frames.Select(f => f.Station.Address).Should().Equal(2, 3);
        plan.Values.Select(v => v.Slices[0].FrameIndex).Should().Equal(0, 1);
    }

    private static IEnumerable<WatchedItem> Items(params string[] addresses) => addresses.Select(a => new WatchedItem(Cpu2, PlcAddress.Parse(a)));

    private static ReplySlice Slice(PollPlan plan, string address) =>
        plan.Values.Single(v => v.Item.Address == PlcAddress.Parse(address)).Slices.Single();
}
