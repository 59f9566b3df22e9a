using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>A PPI bus's plan: one poll frame per S7 item of PpiReadPlanner, each value's slice in its item.</summary>
public sealed class PpiPollPlannerTests
{
    private static readonly Station Cpu2 = new(2);

    [Fact]
    public void Build_MergedRangesPerArea_OneFramePerItemAndSlicesInThem()
    {
        var plan = PpiPollPlanner.Build(Items("VB100", "VW102", "M0.3", "MB1", "VB200"));

        plan.Frames.Select(f => f.PpiItem).Should().Equal(
            S7Item.Bytes(S7Area.M, 0, 2), S7Item.Bytes(S7Area.V, 100, 4), S7Item.Bytes(S7Area.V, 200, 1));
        plan.Frames.Should().OnlyContain(f => f.Items.IsEmpty);
        Slice(plan, "VW102").Should().Be(new ReplySlice(1, 2, 2));
        Slice(plan, "M0.3").Should().Be(new ReplySlice(0, 0, 1));
        Slice(plan, "VB200").Should().Be(new ReplySlice(2, 0, 1));
    }

    [Fact]
    public void Build_AnalogSBitsTimersAndCounters_ReadByTheirOwnItemsWithTheCurrentValueSliced()
    {
        var plan = PpiPollPlanner.Build(Items("AIW0", "AIW4", "AQW2", "SB1", "S0.3", "T37", "T38", "C5"), new Dictionary<Station, CpuProfile> { [Cpu2] = CpuProfiles.For(CpuModel.Cpu224) });

        plan.Rejected.Should().BeEmpty();
        plan.Frames.Select(f => f.PpiItem).Should().BeEquivalentTo(new S7Item?[]
        {
            S7Item.Bytes(S7Area.S, 0, 2), S7Item.Words(S7Area.AI, 0, 3), S7Item.Words(S7Area.AQ, 2, 1), S7Item.Timers(37, 2), S7Item.Counters(5, 1),
        });
        var timers = plan.Frames.ToList().FindIndex(f => f.PpiItem!.Value.Area == S7Area.T);
        var counters = plan.Frames.ToList().FindIndex(f => f.PpiItem!.Value.Area == S7Area.C);
        Slice(plan, "T37").Should().Be(new ReplySlice(timers, 3, 2), "the low word of timer 37's 4-byte value, after its status byte");
        Slice(plan, "T38").Should().Be(new ReplySlice(timers, 8, 2));
        Slice(plan, "C5").Should().Be(new ReplySlice(counters, 3, 2));
        Slice(plan, "AIW4").Should().Be(new ReplySlice(plan.Frames.ToList().FindIndex(f => f.PpiItem!.Value.Area == S7Area.AI), 4, 2));
        plan.Frames[timers].DataBytes.Should().Be(10);
    }

    [Fact]
    public void Build_AddressBeyondTheCpu_RejectedWithTheReason()
    {
        var plan = PpiPollPlanner.Build(Items("VB100", "VB9000", "AIW0", "T256"), new Dictionary<Station, CpuProfile> { [Cpu2] = CpuProfiles.For(CpuModel.Cpu221) });

        plan.Rejected.Select(r => (r.Item.Address.ToString(), r.Reason)).Should().BeEquivalentTo(new[]
        {
            ("VB9000", "VB9000 is past the last V byte VB2047 of CPU 221"),
            ("AIW0", "AIW0: CPU 221 has no analog inputs (AIW)"),
            ("T256", "T256 is past the last timer T255 of CPU 221"),
        });
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
