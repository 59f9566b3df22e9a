using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Differential;

namespace OperatorPanel.StlGen.Tests.Changes;

/// <summary>
/// 09 READ CHANGES OF LISTS of the generated handler, executed in the STL interpreter, against the reference model
/// byte for byte (every exchange goes through <see cref="ChangesExchange"/>): idle lists, pairs in several lists, each
/// reason for a REREAD entry (no copy, copy not valid, pairs not shorter, pairs that do not fit before LAST_FREE) and
/// the 08 that follows it, and the checks 04, 06 and 07 in their order. After every reply the panel's view of each list
/// it still knows is the list's bytes as the memory holds them.
/// </summary>
public sealed class ReadChangesOfListsDifferentialTests
{
    private static readonly ReadItem[][] Lists =
    [
        [new(ProtocolArea.V, 100, 4), new(ProtocolArea.M, 0, 2), new(ProtocolArea.Q, 0, 1), new(ProtocolArea.V, 200, 10)],
        [new(ProtocolArea.V, 300, 12)],
        [new(ProtocolArea.V, 400, 6), new(ProtocolArea.M, 4, 2)],
        [new(ProtocolArea.V, 500, 3)],
    ];

    [Fact]
    public void ReadChangesOfLists_TwoIdleLists_AnswersKZeroForEachIn36Characters()
    {
        var (harness, panel) = Station();
        DefineAndFill(panel, 2);

        var (stl, _) = panel.Raw(new FreeportFrame(2, panel.NextSequence(), (byte)CommandCode.ReadChangesOfLists, [0b0011]));
        var idle = panel.ReadChangesOfLists(0b0011);

        Entries(idle).Should().Equal((1, false, 0), (2, false, 0));
        (ProtocolLimits.RequestChars(1) + stl.Length).Should().Be(14 + 22, "one exchange of 36 characters for both lists, one 08's cost");
        AssertKnown(harness, panel, 2);
    }

    [Fact]
    public void ReadChangesOfLists_FourLists_AnswersPairsInEachChangedListAndKZeroInTheOthers()
    {
        var (harness, panel) = Station();
        DefineAndFill(panel, 4);
        panel.ReadChangesOfLists(0b1111);

        harness.Poke(ProtocolArea.V, 205, (byte)~harness.Reference.Memory.V[205]);
        harness.Poke(ProtocolArea.V, 401, (byte)~harness.Reference.Memory.V[401]);
        harness.Poke(ProtocolArea.M, 5, (byte)~harness.Reference.Memory.M[5]);
        var changed = panel.ReadChangesOfLists(0b1111);
        var idle = panel.ReadChangesOfLists(0b1101);

        Entries(changed).Should().Equal((1, false, 1), (2, false, 0), (3, false, 2), (4, false, 0));
        changed.Lists[0].Changes.Single().Index.Should().Be(4 + 2 + 1 + 5, "V205 in list 1's data");
        changed.Lists[2].Changes.Select(c => (int)c.Index).Should().Equal(1, 6 + 1);
        Entries(idle).Should().Equal((1, false, 0), (3, false, 0), (4, false, 0));
        AssertKnown(harness, panel, 4);
    }

    [Fact]
    public void ReadChangesOfLists_ListWhoseCopyIsNotValid_AnswersRereadAndItsNextReadChangesIsWhole()
    {
        var (harness, panel) = Station();
        panel.Define(1, Lists[0]);
        panel.Define(2, Lists[1]);
        panel.ReadChanges(1);

        var entries = panel.ReadChangesOfLists(0b0011);
        var whole = panel.ReadChanges(2);

        Entries(entries).Should().Equal((1, false, 0), (2, true, 0));
        whole.Full.Should().BeTrue("a just-defined copy is filled by a whole-list answer first");
        panel.ReadChangesOfLists(0b0011).Lists.Should().OnlyContain(l => !l.Reread && l.Changes.IsEmpty);
        AssertKnown(harness, panel, 2);
    }

    [Theory]
    [InlineData(0)]
    [InlineData(16)]
    public void ReadChangesOfLists_ListWithoutCopy_AlwaysAnswersReread(int copyBytes)
    {
        // 16 copy bytes: list 1 (17 bytes) gets none, list 2 (12 bytes) gets one; 0 copy bytes: neither has one.
        var (harness, panel) = Station(copyBytes);
        DefineAndFill(panel, 2);

        var first = panel.ReadChangesOfLists(0b0011);
        var second = panel.ReadChangesOfLists(0b0011);

        Entries(first).Should().Equal((1, true, 0), (2, copyBytes == 0, 0));
        Entries(second).Should().Equal(Entries(first));
        panel.ReadChanges(1).Full.Should().BeTrue();
        AssertKnown(harness, panel, 2);
    }

    [Fact]
    public void ReadChangesOfLists_PairsNotShorterThanTheList_AnswersRereadThenTheNextReadChangesAnswersWhole()
    {
        var (harness, panel) = Station();
        DefineAndFill(panel, 4);

        // List 4 has 3 bytes: 2 changes take 4 bytes as pairs (2K >= D).
        harness.Poke(ProtocolArea.V, 500, (byte)~harness.Reference.Memory.V[500], (byte)~harness.Reference.Memory.V[501]);
        var entries = panel.ReadChangesOfLists(0b1001);
        var afterwards = panel.ReadChanges(4, full: false);

        Entries(entries).Should().Equal((1, false, 0), (4, true, 0));
        afterwards.Full.Should().BeTrue("the REREAD left the copy invalid, so 08 without FULL answers the whole list");
        afterwards.Data.Should().Equal(harness.Reference.Memory.V.AsSpan(500, 3).ToArray());
        panel.ReadChangesOfLists(0b1000).Lists.Single().Should().Match<ListChanges>(l => !l.Reread && l.Changes.IsEmpty);
        AssertKnown(harness, panel, 4);
    }

    [Fact]
    public void ReadChangesOfLists_PairsThatDoNotFitBeforeTheStoredLists_AnswersRereadForThoseLists()
    {
        // Four lists of 10 two-byte items: the tail holds 160 bytes, LAST_FREE = 95. Nine changes in each list: 18 pair
        // bytes are shorter than 20 data bytes, but only the first list's pairs fit (18 + 2 x (19 + 3) = 62 <= 95; the
        // second's would end at 18 + 2 x (38 + 2) = 98).
        var (harness, panel, lists) = FourTailLists();
        for (var list = 0; list < 4; list++)
        {
            ChangeItems(harness, list, 9);
        }

        var entries = panel.ReadChangesOfLists(0b1111);
        var second = panel.ReadChanges(2);

        Entries(entries).Should().Equal((1, false, 9), (2, true, 0), (3, true, 0), (4, true, 0));
        second.Full.Should().BeTrue();
        panel.ReadChangesOfLists(0b0001).Lists.Single().Changes.Should().BeEmpty();
        for (var l = 1; l <= 2; l++)
        {
            panel.Known(l).Should().Equal(lists[l - 1].SelectMany(item => harness.Reference.Memory.V.AsSpan(item.Offset, item.Length).ToArray()));
        }
    }

    [Theory]
    [InlineData(0b1111, 8, false)]
    [InlineData(0b1111, 9, true)]
    [InlineData(0b0111, 8, false)]
    [InlineData(0b0111, 9, true)]
    public void ReadChangesOfLists_PairsEndingJustBeforeLastFree_FitAndOneMorePairDoesNot(byte mask, int changed, bool reread)
    {
        // LAST_FREE = 95. List 1: 9 pairs (P = 19). List 2 with K pairs and R lists after it: the reply ends at
        // 18 + 2 x (19 + 1 + 2K + R). R = 2: 94 with 8 pairs fits, 98 with 9 does not; R = 1: 92 fits, 96 does not.
        var (harness, panel, _) = FourTailLists();
        ChangeItems(harness, 0, 9);
        ChangeItems(harness, 1, changed);

        var entries = panel.ReadChangesOfLists(mask);

        Entries(entries).Should().Equal(new[] { (1, false, 9), (2, reread, reread ? 0 : changed), (3, false, 0), (4, false, 0) }.Take(mask == 0b1111 ? 4 : 3));
    }

    /// <summary>
    /// Issue 23: docs/protocol-v2.md section 2's example of copies (COPY_BYTES 120, lists of D = 100, 30 and 20): the third
    /// list's copy ends at the last copy byte, the last byte of V, where the comparison's double-word compare of a short
    /// chunk read past V and the station went silent for good. It answers K = 00 on every CPU.
    /// </summary>
    [Theory]
    [InlineData(CpuModel.Cpu221)]
    [InlineData(CpuModel.Cpu222)]
    [InlineData(CpuModel.Cpu224)]
    [InlineData(CpuModel.Cpu224XP)]
    [InlineData(CpuModel.Cpu226)]
    public void ReadChangesOfLists_CopyEndingAtTheLastVByte_AnswersKZeroAndKeepsAnswering(CpuModel cpu)
    {
        var options = new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(cpu), Station = 2 };
        var harness = new DifferentialHarness(options, new Random(17));
        var panel = new ChangesExchange(harness, 2);
        panel.Define(1, new ReadItem(ProtocolArea.V, 100, 100));
        panel.Define(2, new ReadItem(ProtocolArea.V, 300, 30));
        panel.Define(3, new ReadItem(ProtocolArea.V, 400, 20));
        panel.ReadChanges(1).Full.Should().BeTrue();
        panel.ReadChanges(3).Full.Should().BeTrue();

        var idle = panel.ReadChangesOfLists(0b0101);
        var again = panel.ReadChangesOfLists(0b0101);

        Entries(idle).Should().Equal((1, false, 0), (3, false, 0));
        Entries(again).Should().Equal(Entries(idle), "the station still answers");
    }

    [Theory]
    [InlineData(new byte[] { }, "04")]
    [InlineData(new byte[] { 0b0011, 0 }, "04")]
    [InlineData(new byte[] { 0, 0 }, "04")]
    [InlineData(new byte[] { 0 }, "06")]
    [InlineData(new byte[] { 0x10 }, "06")]
    [InlineData(new byte[] { 0x13 }, "06")]
    [InlineData(new byte[] { 0x14 }, "06")]
    [InlineData(new byte[] { 0b0100 }, "07")]
    [InlineData(new byte[] { 0b1011 }, "07")]
    public void ReadChangesOfLists_BadLengthMaskOrUndefinedList_AnswersTheFirstFailingCheckLikeTheReference(byte[] payload, string status)
    {
        var (_, panel) = Station();
        panel.Define(1, Lists[0]);
        panel.Define(2, Lists[1]);

        var (stl, reference) = panel.Raw(new FreeportFrame(2, panel.NextSequence(), (byte)CommandCode.ReadChangesOfLists, [.. payload]));

        stl.Should().Be(reference);
        stl.Substring(5, 4).Should().Be("89" + status);
    }

    private static (DifferentialHarness Harness, ChangesExchange Panel) Station(int copyBytes = HandlerDefaults.CopyBytes)
    {
        var options = new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2, CopyBytes = copyBytes };
        var harness = new DifferentialHarness(options, new Random(13));
        return (harness, new ChangesExchange(harness, 2));
    }

    /// <summary>Lists 1-4 of 10 two-byte items each at VB600-VB679, read whole once: the tail holds 160 bytes, LAST_FREE = 95.</summary>
    private static (DifferentialHarness Harness, ChangesExchange Panel, ReadItem[][] Lists) FourTailLists()
    {
        var (harness, panel) = Station();
        var lists = Enumerable.Range(0, 4).Select(l => Enumerable.Range(0, 10).Select(i => new ReadItem(ProtocolArea.V, 600 + (l * 20) + (2 * i), 2)).ToArray()).ToArray();
        for (var l = 0; l < 4; l++)
        {
            panel.Define(l + 1, lists[l]);
        }

        for (var l = 1; l <= 4; l++)
        {
            panel.ReadChanges(l).Full.Should().BeTrue();
        }

        return (harness, panel, lists);
    }

    /// <summary>The first byte of the first <paramref name="items"/> items of tail list <paramref name="list"/> (0-3) inverted.</summary>
    private static void ChangeItems(DifferentialHarness harness, int list, int items)
    {
        var at = 600 + (list * 20);
        harness.Poke(ProtocolArea.V, at, [.. harness.Reference.Memory.V.AsSpan(at, 2 * items).ToArray().Select((b, n) => n % 2 == 0 ? (byte)~b : b)]);
    }

    /// <summary>Lists 1 .. <paramref name="count"/> defined and read whole once (their copies valid, where they have one).</summary>
    private static void DefineAndFill(ChangesExchange panel, int count)
    {
        for (var list = 1; list <= count; list++)
        {
            panel.Define(list, Lists[list - 1]);
        }

        for (var list = 1; list <= count; list++)
        {
            panel.ReadChanges(list).Full.Should().BeTrue();
        }
    }

    private static IEnumerable<(int List, bool Reread, int K)> Entries(ReadChangesOfListsResponse response) =>
        response.Lists.Select(l => (l.List, l.Reread, l.Changes.Length));

    private static void AssertKnown(DifferentialHarness harness, ChangesExchange panel, int count)
    {
        foreach (var list in Enumerable.Range(1, count).Where(panel.Knows))
        {
            panel.Known(list).Should().Equal(Lists[list - 1].SelectMany(i => harness.Reference.Memory.Area(i.Area).AsSpan(i.Offset, i.Length).ToArray()), $"list {list}");
        }
    }
}
