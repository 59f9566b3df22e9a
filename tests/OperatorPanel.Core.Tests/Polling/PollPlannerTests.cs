using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Polling;

public sealed class PollPlannerTests
{
    [Fact]
    public void Build_TouchingAndOverlappingAddresses_ReadAsOneBlock()
    {
        var plan = PollPlanner.Build(Items(One, "VB10", "VW11", "VD12", "V13.2"));

        Frames(plan).Should().Equal("1: V10+6");
    }

    [Theory]
    [InlineData("VB1", "1: V0+2")] // touching
    [InlineData("VB2", "1: V0+3")] // 1 gap byte: 2 chars < 8 chars of another item
    [InlineData("VB4", "1: V0+5")] // 3 gap bytes: 6 chars < 8
    [InlineData("VB5", "1: V0+1 V5+1")] // 4 gap bytes: 8 chars = 8, a tie keeps the smaller read
    [InlineData("VB20", "1: V0+1 V20+1")]
    public void Build_GapBetweenTwoBytes_MergedOnlyWhenCheaperThanAnItem(string second, string expected)
    {
        var plan = PollPlanner.Build(Items(One, "VB0", second));

        Frames(plan).Should().Equal(expected);
    }

    [Fact]
    public void Build_BitsOfNeighbouringBytes_MergeIntoOneBlock()
    {
        var plan = PollPlanner.Build(Items(One, "M0.0", "M0.7", "M1.3"));

        Frames(plan).Should().Equal("1: M0+2");
    }

    [Fact]
    public void Build_DifferentAreas_ShareOneFrameButNeverOneBlock()
    {
        var plan = PollPlanner.Build(Items(One, "SMB0", "VB0", "MB0", "QB0", "IB0"));

        Frames(plan).Should().Equal("1: I0+1 Q0+1 M0+1 V0+1 SM0+1");
    }

    [Fact]
    public void Build_RangeLongerThanOneReply_IsSplitAt121Bytes()
    {
        var dwords = Enumerable.Range(0, 50).Select(i => $"VD{i * 4}").ToArray();

        var plan = PollPlanner.Build(Items(One, dwords));

        Frames(plan).Should().Equal("1: V0+121", "1: V121+79");
        plan.Values.Single(v => v.Item == Item(One, "VD120")).Slices.Should().Equal(new ReplySlice(0, 120, 1), new ReplySlice(1, 0, 3));
    }

    [Fact]
    public void Build_NineFarApartBytes_BridgesOneGapToSaveAFrame()
    {
        // Nine items need two frames; bridging one 10-byte gap (20 reply chars) saves an item (8) and a frame
        // (12 + 12 + 20 turnaround + 8 for its item): 178 -> 146 characters. A second bridge would only add cost.
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 9).Select(i => $"VB{i * 11}")]));

        Frames(plan).Should().Equal("1: V0+12 V22+1 V33+1 V44+1 V55+1 V66+1 V77+1 V88+1");
        plan.CostChars.Should().Be(146);
    }

    [Fact]
    public void Build_SeventeenFarApartBytes_PacksEightItemsPerFrame()
    {
        // 29-byte gaps cost 58 reply chars, more than the 52 an item and a frame cost: nothing is bridged.
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 17).Select(i => $"VB{i * 30}")]));

        Frames(plan).Should().Equal(
            "1: V0+1 V30+1 V60+1 V90+1 V120+1 V150+1 V180+1 V210+1",
            "1: V240+1 V270+1 V300+1 V330+1 V360+1 V390+1 V420+1 V450+1",
            "1: V480+1");
    }

    [Fact]
    public void Build_SeventeenBytesWithSmallerGaps_BridgesOneGapToDropAFrame()
    {
        // 14-byte gaps cost 28 chars: one bridge leaves 16 items in two frames, saving 52.
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 17).Select(i => $"MB{i * 15}")]));

        Frames(plan).Should().Equal(
            "1: M0+16 M30+1 M45+1 M60+1 M75+1 M90+1 M105+1 M120+1",
            "1: M135+1 M150+1 M165+1 M180+1 M195+1 M210+1 M225+1 M240+1");
    }

    [Fact]
    public void Build_BlocksOverflowingOneReply_PackedLongestFirst()
    {
        // 100 + 30 + 20 bytes: the 100-byte block and the 20-byte block fill one reply (120), the 30-byte block gets its own.
        var plan = PollPlanner.Build(
            [.. Enumerable.Range(0, 25).Select(i => Item(One, $"VD{i * 4}")),
            .. Enumerable.Range(0, 15).Select(i => Item(One, $"MW{i * 2}")),
            .. Enumerable.Range(0, 20).Select(i => Item(One, $"QB{i}"))]);

        Frames(plan).Should().Equal("1: Q0+20 V0+100", "1: M0+30");
    }

    [Fact]
    public void Build_TwoStations_NeverShareAFrame()
    {
        var plan = PollPlanner.Build([Item(Two, "VB0"), Item(One, "VB0"), Item(One, "IB0")]);

        Frames(plan).Should().Equal("1: I0+1 V0+1", "2: V0+1");
        plan.Stations.Should().Equal(One, Two);
    }

    [Fact]
    public void Build_AreaNotServedByTheLink_IsRejectedWithReason()
    {
        var plan = PollPlanner.Build(Items(One, "AIW0", "VB0"));

        plan.Rejected.Should().Equal(new PlanRejection(Item(One, "AIW0"), "AIW0: the panel link reads only I, Q, M, V and SM"));
        Frames(plan).Should().Equal("1: V0+1");
    }

    [Fact]
    public void Build_AddressPastTheCpuArea_IsRejectedOnlyWhenTheCpuIsKnown()
    {
        var cpus = new Dictionary<Station, CpuProfile> { [One] = CpuProfiles.For(CpuModel.Cpu221) };

        var known = PollPlanner.Build(Items(One, "VB2048"), cpus);
        var unknown = PollPlanner.Build(Items(One, "VB2048"));

        known.Rejected.Should().ContainSingle().Which.Reason.Should().Contain("VB2048").And.Contain("CPU 221");
        known.Frames.Should().BeEmpty();
        Frames(unknown).Should().Equal("1: V2048+1");
    }

    [Fact]
    public void Build_Figures_CountFramesCharactersAndBytes()
    {
        var plan = PollPlanner.Build(Items(One, "IB0", "QB0", "VW100"));

        plan.FrameCount.Should().Be(1);
        plan.RequestChars.Should().Be(12 + (3 * 8));
        plan.ReplyChars.Should().Be(12 + (4 * 2));
        plan.DataBytes.Should().Be(4);
        plan.CostChars.Should().Be(36 + 20 + 20);
    }

    [Fact]
    public void Build_DuplicateItems_AreWatchedOnce()
    {
        var plan = PollPlanner.Build(Items(One, "VW10", "VW10"));

        plan.Values.Should().ContainSingle().Which.Slices.Should().Equal(new ReplySlice(0, 0, 2));
    }

    [Fact]
    public void Build_HigherTurnaroundCost_BridgesWiderGapsToSaveFrames()
    {
        var slowBus = PollCostModel.Default with { TurnaroundChars = 200 };
        var items = Items(One, [.. Enumerable.Range(0, 9).Select(i => $"VB{i * 41}")]);

        // Default: 178 chars in two frames beats 206 in one (40 gap bytes = 80 chars). At 200 chars of turnaround: 538 vs 386.
        Frames(PollPlanner.Build(items)).Should().HaveCount(2);
        Frames(PollPlanner.Build(items, costModel: slowBus)).Should().Equal("1: V0+42 V82+1 V123+1 V164+1 V205+1 V246+1 V287+1 V328+1");
    }

    private static List<string> Frames(PollPlan plan) =>
        [.. plan.Frames.Select(f => $"{f.Station.Address}: {string.Join(' ', f.Items.Select(Describe))}")];

    private static string Describe(ReadItem item) => $"{item.Area}{item.Offset}+{item.Length}";
}
