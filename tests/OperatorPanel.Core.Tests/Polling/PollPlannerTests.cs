using OperatorPanel.Core.Addressing;
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
    public void Build_RangeLongerThanOneReply_IsSplitAt119Bytes()
    {
        var dwords = Enumerable.Range(0, 50).Select(i => $"VD{i * 4}").ToArray();

        var plan = PollPlanner.Build(Items(One, dwords));

        Frames(plan).Should().Equal("1: V0+119", "1: V119+81");
        plan.Values.Single(v => v.Item == Item(One, "VD116")).Slices.Should().Equal(new ReplySlice(0, 116, 3), new ReplySlice(1, 0, 1));
    }

    [Fact]
    public void Build_TwelveFarApartBytes_ReadAsTwelveItemsOfOneFrameWithoutBridging()
    {
        // 19-byte gaps cost 38 reply chars each, an item 8: with up to 20 items per READ nothing is worth bridging.
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 12).Select(i => $"VB{i * 20}")]));

        Frames(plan).Should().Equal("1: " + Singles("V", 0, 20, 12));
        plan.CostChars.Should().Be(12 + (12 * 8) + 12 + (12 * 2) + 20);
    }

    [Fact]
    public void Build_TwentyOneFarApartBytes_BridgesOneGapToSaveAFrame()
    {
        // 21 items need two frames (298 chars); bridging one 10-byte gap (20 reply chars) saves an item (8) and a frame
        // (12 + 12 + 20 turnaround): 266 characters. A second bridge would only add cost (278).
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 21).Select(i => $"VB{i * 11}")]));

        Frames(plan).Should().Equal("1: V0+12 " + Singles("V", 22, 11, 19));
        plan.CostChars.Should().Be(266);
    }

    [Fact]
    public void Build_FortyOneFarApartBytes_PacksTwentyItemsPerFrame()
    {
        // 29-byte gaps cost 58 reply chars, more than the 52 an item and a frame cost: nothing is bridged.
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 41).Select(i => $"VB{i * 30}")]));

        Frames(plan).Should().Equal("1: " + Singles("V", 0, 30, 20), "1: " + Singles("V", 600, 30, 20), "1: V1200+1");
    }

    [Fact]
    public void Build_FortyOneBytesWithSmallerGaps_BridgesOneGapToDropAFrame()
    {
        // 14-byte gaps cost 28 chars: one bridge leaves 40 items in two frames, saving 52.
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 41).Select(i => $"MB{i * 15}")]));

        Frames(plan).Should().Equal("1: M0+16 " + Singles("M", 30, 15, 19), "1: " + Singles("M", 315, 15, 20));
    }

    [Fact]
    public void Build_ElevenTenByteBlocks_SplitByTheDataRuleBeforeTheItemLimit()
    {
        // Ten 10-byte blocks fill a reply (2 x 100 + 4 x 10 = 240 <= 243); an eleventh would need 264, though 11 items
        // are far below 20. 90-byte gaps are never worth bridging.
        var plan = PollPlanner.Build(
            [.. Enumerable.Range(0, 11).SelectMany(i => new[] { Item(One, $"VD{i * 100}"), Item(One, $"VD{(i * 100) + 4}"), Item(One, $"VW{(i * 100) + 8}") })]);

        Frames(plan).Should().Equal("1: " + string.Join(' ', Enumerable.Range(0, 10).Select(i => $"V{i * 100}+10")), "1: V1000+10");
        plan.Frames.Should().OnlyContain(f => plan.CostModel.Fits(f.Items.Length, f.DataBytes));
    }

    [Fact]
    public void Build_BlocksOverflowingOneReply_PackedLongestFirst()
    {
        // 96 + 30 + 20 bytes: the 96-byte block and the 20-byte block fill a two-item reply (116 of at most 117), the
        // 30-byte block gets its own.
        var plan = PollPlanner.Build(
            [.. Enumerable.Range(0, 24).Select(i => Item(One, $"VD{i * 4}")),
            .. Enumerable.Range(0, 15).Select(i => Item(One, $"MW{i * 2}")),
            .. Enumerable.Range(0, 20).Select(i => Item(One, $"QB{i}"))]);

        Frames(plan).Should().Equal("1: Q0+20 V0+96", "1: M0+30");
    }

    [Fact]
    public void Build_TwoBlocksJustOverTheTwoItemLimit_TakeTwoFrames()
    {
        // 100 + 18 = 118 bytes would fit one item's 119 but not two items' 117.
        var plan = PollPlanner.Build(
            [.. Enumerable.Range(0, 25).Select(i => Item(One, $"VD{i * 4}")),
            .. Enumerable.Range(0, 9).Select(i => Item(One, $"MW{i * 2}"))]);

        Frames(plan).Should().Equal("1: M0+18", "1: V0+100");
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
        var items = Items(One, [.. Enumerable.Range(0, 21).Select(i => $"VB{i * 41}")]);

        // Default: 298 chars in two frames beats 326 in one (40 gap bytes = 80 chars). At 200 chars of turnaround: 658 vs 506.
        Frames(PollPlanner.Build(items)).Should().HaveCount(2);
        Frames(PollPlanner.Build(items, costModel: slowBus)).Should().Equal("1: V0+42 " + Singles("V", 82, 41, 19));
    }

    private static List<string> Frames(PollPlan plan) =>
        [.. plan.Frames.Select(f => $"{f.Station.Address}: {string.Join(' ', f.Items.Select(Describe))}")];

    private static string Describe(ReadItem item) => $"{item.Area}{item.Offset}+{item.Length}";

    /// <summary>"V0+1 V20+1 …": <paramref name="count"/> one-byte blocks from <paramref name="first"/>, <paramref name="step"/> apart.</summary>
    private static string Singles(string area, int first, int step, int count) =>
        string.Join(' ', Enumerable.Range(0, count).Select(i => $"{area}{first + (i * step)}+1"));
}
