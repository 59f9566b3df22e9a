using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>List-aware planning: stored lists for any tag count, within the buffer rules of docs/protocol-v2.md v2.</summary>
public sealed class PollPlannerListTests
{
    /// <summary>
    /// The reference line of `opanel bench link` (src/OperatorPanel.Cli/Bench/ReferenceLine.cs): CPU 226, 101 items,
    /// 74 distinct bytes in 26 ranges.
    /// </summary>
    private static readonly string[] ReferenceLine =
    [
        "IB0", "IB1", "IB2", "QB0", "QB1",
        "VW100", "VD104", "VD112", "VW120", "VB124", "VB130", "VD140", "VW150", "VB170", "V180.0",
        "VD400", "VD408", "VW420", "VB430", "V440.2", "V440.5", "VW456",
        "VW1000", "VD1004", "VW1012", "VB1020", "VB1024", "VD1030", "V1040.1",
        "M0.0", "M0.5", "M1.2", "M1.7", "MB2", "MB3", "MW4", "MD6",
        .. Enumerable.Range(10, 8).SelectMany(b => Enumerable.Range(0, 8).Select(bit => $"M{b}.{bit}")),
    ];

    [Fact]
    public void Build_ReferenceLine_ReadsEverythingThroughTwoListsWithoutGapBytes()
    {
        var plan = PollPlanner.Build(Items(Two, ReferenceLine), Cpu226(Two));

        // One list cannot hold it: 26 ranges need 4 x 26 tail bytes + 20 + 2 x 74 reply characters = 272 > 255, and
        // bridging a gap of g >= 2 bytes saves 4 tail bytes for 2g reply characters. Two lists need only the largest D.
        plan.Frames.Select(f => f.List).Should().Equal(1, 2);
        plan.DataBytes.Should().Be(74);
        plan.FullRefreshChars.Should().Be(220, "2 x (16 + 20) + 2 x 74");
        plan.FullRefreshChars.Should().BeLessThanOrEqualTo((int)(1.6 * 2 * 74));
        plan.IdleChars.Should().Be(36, "one 09 READ CHANGES OF LISTS (14) answered with K = 0 for each list (18 + 2 x 2)");
    }

    [Fact]
    public void Build_TwoHundredScatteredTags_FillsListsAndReadsTheRestWithReadsThatKeepThem()
    {
        var plan = PollPlanner.Build(Scattered(One, 200, seed: 7), Cpu226(One));

        var lists = plan.Frames.Where(f => f.List is not null).ToList();
        var plain = plan.Frames.Where(f => f.List is null).ToList();
        lists.Should().NotBeEmpty();
        plain.Should().NotBeEmpty();
        lists.Select(f => f.List).Should().Equal(Enumerable.Range(1, lists.Count).Cast<int?>());
        ProtocolLimits.ListsFit(lists.Select(f => (f.Items.Length, f.DataBytes))).Should().BeTrue();
        var tail = lists.Sum(f => 4 * f.Items.Length);
        plain.Should().OnlyContain(f => ProtocolLimits.ReadKeepsLists(tail, f.Items.Length, f.DataBytes));
    }

    [Fact]
    public void Build_TwoStationsWithLists_EveryFrameOnTheBusEndsBelowEveryStationsFloor()
    {
        var plan = PollPlanner.Build([.. Scattered(One, 120, seed: 3), .. Scattered(Two, 40, seed: 4)], Cpu226(One, Two));

        var model = plan.CostModel;
        var highestTail = plan.Frames.Where(f => f.List is not null).GroupBy(f => f.Station).Max(g => g.Sum(f => 4 * f.Items.Length));
        highestTail.Should().BePositive();
        var lastFree = 255 - highestTail;
        foreach (var frame in plan.Frames)
        {
            if (frame.List is null)
            {
                ProtocolLimits.ReadKeepsLists(highestTail, frame.Items.Length, frame.DataBytes).Should().BeTrue();
            }
            else
            {
                model.ListFullReplyChars(frame.DataBytes).Should().BeLessThanOrEqualTo(lastFree);
                model.DefineListRequestChars(frame.Items.Length).Should().BeLessThanOrEqualTo(lastFree);
            }
        }
    }

    [Fact]
    public void Build_ManyTags_LocatesEveryWatchedByteInExactlyTheFramesThatCarryIt()
    {
        var items = Scattered(One, 2000, seed: 11);

        var plan = PollPlanner.Build(items, Cpu226(One));

        plan.Values.Should().HaveCount(items.Distinct().Count());
        foreach (var value in plan.Values)
        {
            var address = value.Item.Address;
            var area = ProtocolAreaExtensions.FromMemoryArea(address.Area)!.Value;
            var bytes = value.Slices.SelectMany(s => Enumerable.Range(s.DataOffset, s.Length).Select(d => ByteAt(plan.Frames[s.FrameIndex], d)));
            bytes.Should().Equal(Enumerable.Range(address.ByteOffset, address.LastByte - address.ByteOffset + 1).Select(b => (area, b)));
        }
    }

    [Fact]
    public void Build_PlainOnlyModel_StoresNoList()
    {
        var plan = PollPlanner.Build(Items(Two, ReferenceLine), Cpu226(Two), PollCostModel.Default with { MaxListsPerStation = 0 });

        plan.ListCount.Should().Be(0);
        plan.IdleChars.Should().Be(plan.FullRefreshChars);
    }

    [Fact]
    public void Build_TwoStationsWithTwoListsEach_IdlePricesOne09PerStation()
    {
        var plan = PollPlanner.Build([.. Items(One, ReferenceLine), .. Items(Two, ReferenceLine)], Cpu226(One, Two));

        plan.ListCount.Should().Be(4);
        plan.IdleChars.Should().Be(2 * (14 + 18 + (2 * 2)), "per station one 09 and a K = 0 for each of its two lists");
    }

    /// <summary>Which (area, byte) the reply byte <paramref name="dataOffset"/> of <paramref name="frame"/> carries.</summary>
    private static (ProtocolArea, int) ByteAt(PollFrame frame, int dataOffset)
    {
        foreach (var item in frame.Items)
        {
            if (dataOffset < item.Length)
            {
                return (item.Area, item.Offset + dataOffset);
            }

            dataOffset -= item.Length;
        }

        throw new InvalidOperationException("past the frame's data");
    }

    private static Dictionary<Station, CpuProfile> Cpu226(params Station[] stations) =>
        stations.ToDictionary(s => s, _ => CpuProfiles.For(CpuModel.Cpu226, CpuRevision.Current));

    /// <summary>Bits, bytes, words and double words scattered over VB0-VB9999 and MB0-MB31, from a fixed seed.</summary>
    private static List<WatchedItem> Scattered(Station station, int count, int seed)
    {
        var random = new Random(seed);
        string[] widths = ["B", "W", "D"];
        return [.. Enumerable.Range(0, count).Select(_ => random.Next(4) switch
        {
            0 => Item(station, $"M{random.Next(32)}.{random.Next(8)}"),
            1 => Item(station, $"V{random.Next(10000)}.{random.Next(8)}"),
            _ => Item(station, $"V{widths[random.Next(3)]}{random.Next(10000)}"),
        })];
    }
}
