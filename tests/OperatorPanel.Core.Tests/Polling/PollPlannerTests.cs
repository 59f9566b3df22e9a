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
        var plan = PollPlanner.Build(Items(One, "VB0", second), costModel: Plain);

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
        var plan = PollPlanner.Build(Items(One, "VB0", "MB0", "QB0", "IB0"));

        Frames(plan).Should().Equal("1: I0+1 Q0+1 M0+1 V0+1");
    }

    [Fact]
    public void Build_RangeLongerThanOneReply_IsSplitAt116Bytes()
    {
        var bytes = Enumerable.Range(0, 200).Select(i => $"VB{i}").Append("VD114").ToArray();

        var plan = PollPlanner.Build(Items(One, bytes), costModel: Plain);

        Frames(plan).Should().Equal("1: V0+116", "1: V116+84");
        plan.Values.Single(v => v.Item == Item(One, "VD114")).Slices.Should().Equal(new ReplySlice(0, 114, 2), new ReplySlice(1, 0, 2));
    }

    [Fact]
    public void Build_TwelveFarApartBytes_ReadAsTwelveItemsOfOneFrameWithoutBridging()
    {
        // 19-byte gaps cost 38 reply chars each, an item 8: with up to 20 items per READ nothing is worth bridging.
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 12).Select(i => $"VB{i * 20}")]), costModel: Plain);

        Frames(plan).Should().Equal("1: " + Singles("V", 0, 20, 12));
        plan.CostChars.Should().Be(14 + (12 * 8) + 18 + (12 * 2) + 20);
    }

    [Fact]
    public void Build_TwentyOneFarApartBytes_BridgesOneGapToSaveAFrame()
    {
        // 21 items need two frames (314 chars); bridging one 10-byte gap (20 reply chars) saves an item (8) and a frame
        // (14 + 18 + 20 turnaround): 274 characters. A second bridge would only add cost (286).
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 21).Select(i => $"VB{i * 11}")]), costModel: Plain);

        Frames(plan).Should().Equal("1: V0+12 " + Singles("V", 22, 11, 19));
        plan.CostChars.Should().Be(274);
    }

    [Fact]
    public void Build_FortyOneFarApartBytes_PacksTwentyItemsPerFrame()
    {
        // 31-byte gaps cost 62 reply chars, more than the 60 an item and a frame cost: nothing is bridged.
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 41).Select(i => $"VB{i * 32}")]), costModel: Plain);

        Frames(plan).Should().Equal("1: " + Singles("V", 0, 32, 20), "1: " + Singles("V", 640, 32, 20), "1: V1280+1");
    }

    [Fact]
    public void Build_FortyOneBytesWithSmallerGaps_BridgesOneGapToDropAFrame()
    {
        // 14-byte gaps cost 28 chars: one bridge leaves 40 items in two frames, saving 60.
        var plan = PollPlanner.Build(Items(One, [.. Enumerable.Range(0, 41).Select(i => $"MB{i * 15}")]), costModel: Plain);

        Frames(plan).Should().Equal("1: M0+16 " + Singles("M", 30, 15, 19), "1: " + Singles("M", 315, 15, 20));
    }

    [Fact]
    public void Build_ElevenTenByteBlocks_SplitByTheDataRuleBeforeTheItemLimit()
    {
        // Nine 10-byte blocks fill a reply (2 x 90 + 4 x 9 = 216 <= 237); a tenth would need 240, though 10 items
        // are far below 20. 90-byte gaps are never worth bridging.
        var plan = PollPlanner.Build(
            [.. Enumerable.Range(0, 11).SelectMany(i => new[] { Item(One, $"VD{i * 100}"), Item(One, $"VD{(i * 100) + 4}"), Item(One, $"VW{(i * 100) + 8}") })],
            costModel: Plain);

        Frames(plan).Should().Equal("1: " + string.Join(' ', Enumerable.Range(0, 9).Select(i => $"V{i * 100}+10")), "1: V900+10 V1000+10");
        plan.Frames.Should().OnlyContain(f => plan.CostModel.Fits(f.Items.Length, f.DataBytes));
    }

    [Fact]
    public void Build_BlocksOverflowingOneReply_PackedLongestFirst()
    {
        // 92 + 30 + 20 bytes: the 92-byte block and the 20-byte block fill a two-item reply (112 of at most 114), the
        // 30-byte block gets its own.
        var plan = PollPlanner.Build(
            [.. Enumerable.Range(0, 23).Select(i => Item(One, $"VD{i * 4}")),
            .. Enumerable.Range(0, 15).Select(i => Item(One, $"MW{i * 2}")),
            .. Enumerable.Range(0, 20).Select(i => Item(One, $"QB{i}"))],
            costModel: Plain);

        Frames(plan).Should().Equal("1: Q0+20 V0+92", "1: M0+30");
    }

    [Fact]
    public void Build_TwoBlocksJustOverTheTwoItemLimit_TakeTwoFrames()
    {
        // 100 + 15 = 115 bytes would fit one item's 116 but not two items' 114.
        var plan = PollPlanner.Build(
            [.. Enumerable.Range(0, 25).Select(i => Item(One, $"VD{i * 4}")),
            .. Enumerable.Range(0, 15).Select(i => Item(One, $"MB{i}"))],
            costModel: Plain);

        Frames(plan).Should().Equal("1: M0+15", "1: V0+100");
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
        var plan = PollPlanner.Build(Items(One, "AIW0", "VB0", "T37", "SMW22"));

        plan.Rejected.Should().Equal(new PlanRejection(Item(One, "AIW0"), "AIW0: the Freeport link reads only I, Q, M and V: its handler reaches memory through pointers, and an S7-200 pointer cannot reach analog values; copy the analog value to V in the PLC program (MOVW AIW0, VW100) and watch that, or read the station over PPI (\"protocol\": \"ppi\"), which reads analog values"),
            new PlanRejection(Item(One, "T37"), "T37: the Freeport link reads only I, Q, M and V: its handler leaves timers out to stay small; copy the current value to V in the PLC program (MOVW T37, VW100) and watch that, or read the station over PPI (\"protocol\": \"ppi\"), which reads timers"),
            new PlanRejection(Item(One, "SMW22"), "SMW22: the Freeport link reads only I, Q, M and V: its handler reaches memory through pointers, and no S7-200 manual page found says a pointer reaches SM; copy the SM bytes to V in the PLC program (MOVW SMW22, VW100) and watch that, or read the station over PPI (\"protocol\": \"ppi\"), which reads SM"));
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
    public void Build_FiguresOfAPlainRead_CountDescriptorsEveryCycle()
    {
        var plan = PollPlanner.Build(Items(One, "IB0", "QB0", "VW100"), costModel: Plain);

        plan.FrameCount.Should().Be(1);
        plan.RequestChars.Should().Be(14 + (3 * 8));
        plan.ReplyChars.Should().Be(18 + (4 * 2));
        plan.IdleChars.Should().Be(plan.FullRefreshChars);
        plan.DataBytes.Should().Be(4);
        plan.CostChars.Should().Be(38 + 26 + 20);
    }

    [Fact]
    public void Build_FiguresOfAList_CountReadChangesNotDescriptors()
    {
        var plan = PollPlanner.Build(Items(One, "IB0", "QB0", "VW100"));

        plan.Frames.Should().ContainSingle().Which.List.Should().Be(1);
        plan.RequestChars.Should().Be(16, "READ CHANGES: LIST and FLAGS");
        plan.ReplyChars.Should().Be(20 + (4 * 2), "a FULL answer: K = FF and the data");
        plan.IdleChars.Should().Be(14 + 20, "nothing changed: one 09 READ CHANGES OF LISTS answered with K = 0");
        plan.DefineChars.Should().Be(16 + (3 * 8) + 18);
        plan.CostChars.Should().Be(16 + 20 + 4 + 20, "the planner prices a list byte at 1 character, the midpoint of idle and FULL");
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

        // Default: 314 chars in two frames beats 334 in one (40 gap bytes = 80 chars). At 200 chars of turnaround: 674 vs 514.
        Frames(PollPlanner.Build(items, costModel: Plain)).Should().HaveCount(2);
        Frames(PollPlanner.Build(items, costModel: slowBus with { MaxListsPerStation = 0 })).Should().Equal("1: V0+42 " + Singles("V", 82, 41, 19));
    }

    /// <summary>Plain READs only: the tests of gap bridging and packing.</summary>
    private static readonly PollCostModel Plain = PollCostModel.Default with { MaxListsPerStation = 0 };

    private static List<string> Frames(PollPlan plan) =>
        [.. plan.Frames.Select(f => $"{f.Station.Address}: {string.Join(' ', f.Items.Select(Describe))}")];

    private static string Describe(ReadItem item) => $"{item.Area}{item.Offset}+{item.Length}";

    /// <summary>"V0+1 V20+1 …": <paramref name="count"/> one-byte blocks from <paramref name="first"/>, <paramref name="step"/> apart.</summary>
    private static string Singles(string area, int first, int step, int count) =>
        string.Join(' ', Enumerable.Range(0, count).Select(i => $"{area}{first + (i * step)}+1"));
}
