using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Differential;

namespace OperatorPanel.StlGen.Tests.Changes;

/// <summary>
/// 08 READ CHANGES of the generated handler, executed in the STL interpreter, against the reference model byte for
/// byte: an idle list, a few changes, many changes, the FULL flag, lists without a copy, and the copies after a
/// redefinition and after the lists were cleared. Every reply also moves the panel's view on, which must always be
/// the list's bytes as the memory holds them.
/// </summary>
public sealed class ReadChangesDifferentialTests
{
    private static readonly ReadItem[] Items =
        [new(ProtocolArea.V, 100, 4), new(ProtocolArea.M, 0, 2), new(ProtocolArea.Q, 0, 1), new(ProtocolArea.V, 200, 10)];

    private const int DataBytes = 17;

    [Fact]
    public void ReadChanges_IdleList_AnswersTheWholeListFirstThenNoPairs()
    {
        var (harness, panel) = Station();
        panel.Define(1, Items);

        var first = panel.ReadChanges(1);
        var idle = panel.ReadChanges(1);
        var again = panel.ReadChanges(1);

        first.Full.Should().BeTrue("a new copy is not valid until a whole-list answer filled it");
        first.Data.Should().Equal(Memory(harness));
        (idle.Full, idle.Changes.Length, again.Changes.Length).Should().Be((false, 0, 0));
        ProtocolLimits.RequestChars(2).Should().Be(16, "the idle request");
        ProtocolLimits.ReplyChars(1).Should().Be(20, "the idle reply, K = 0: 36 characters per idle station");
    }

    [Fact]
    public void ReadChanges_AFewBytesChanged_AnswersTheirIndexAndValue()
    {
        var (harness, panel) = Station();
        panel.Define(1, Items);
        panel.ReadChanges(1);

        harness.Poke(ProtocolArea.V, 101, 0x5A);
        harness.Poke(ProtocolArea.M, 1, (byte)~harness.Reference.Memory.M[1]);
        harness.Poke(ProtocolArea.V, 209, (byte)~harness.Reference.Memory.V[209]);
        var changes = panel.ReadChanges(1);

        changes.Full.Should().BeFalse();
        changes.Changes.Select(c => (int)c.Index).Should().Equal([1, 4 + 1, 4 + 2 + 1 + 9], "V101, M1 and V209 in the list's data");
        changes.Changes.Select(c => c.Value).Should().Equal(harness.Reference.Memory.V[101], harness.Reference.Memory.M[1], harness.Reference.Memory.V[209]);
        panel.Known(1).Should().Equal(Memory(harness));
        panel.ReadChanges(1).Changes.Should().BeEmpty("the copy moved on with the reply");
    }

    [Fact]
    public void ReadChanges_HalfTheBytesChanged_AnswersTheWholeList()
    {
        var (harness, panel) = Station();
        panel.Define(1, Items);
        panel.ReadChanges(1);

        // 9 of 17 bytes: 2K >= D, the pairs would not be shorter.
        harness.Poke(ProtocolArea.V, 200, [.. harness.Reference.Memory.V.AsSpan(200, 9).ToArray().Select(b => (byte)~b)]);
        var changed = panel.ReadChanges(1);
        var afterNine = Memory(harness);
        harness.Poke(ProtocolArea.V, 200, [.. harness.Reference.Memory.V.AsSpan(200, 8).ToArray().Select(b => (byte)~b)]);
        var eight = panel.ReadChanges(1);

        changed.Full.Should().BeTrue();
        changed.Data.Should().Equal(afterNine);
        (eight.Full, eight.Changes.Length).Should().Be((false, 8), "8 pairs (2 x 8 < 17) are shorter than the list");
        eight.Changes.Select(c => (int)c.Index).Should().Equal(Enumerable.Range(7, 8));
        panel.Known(1).Should().Equal(Memory(harness));
    }

    [Fact]
    public void ReadChanges_FullFlag_AnswersTheWholeListAndRenewsTheCopy()
    {
        var (harness, panel) = Station();
        panel.Define(1, Items);
        panel.ReadChanges(1);
        harness.Poke(ProtocolArea.Q, 0, (byte)~harness.Reference.Memory.Q[0]);

        var full = panel.ReadChanges(1, full: true);
        var after = panel.ReadChanges(1);

        full.Full.Should().BeTrue();
        full.Data.Should().Equal(Memory(harness));
        after.Changes.Should().BeEmpty("the FULL answer renewed the copy");
    }

    [Theory]
    [InlineData(0)]
    [InlineData(16)]
    public void ReadChanges_ListWithoutCopy_AlwaysAnswersTheWholeList(int copyBytes)
    {
        var (harness, panel) = Station(copyBytes);
        panel.Define(1, Items);
        panel.Define(2, new ReadItem(ProtocolArea.V, 300, 12));

        var answers = Enumerable.Range(0, 3).Select(_ => panel.ReadChanges(1)).ToList();
        panel.ReadChanges(2);
        var second = panel.ReadChanges(2);

        answers.Should().OnlyContain(a => a.Full && a.Data.Length == DataBytes, $"{DataBytes} bytes do not fit {copyBytes} copy bytes");
        second.Full.Should().Be(copyBytes == 0, "list 2's 12 bytes fit 16 copy bytes: defined later, it still gets the copy");
        panel.Known(1).Should().Equal(Memory(harness));
    }

    [Fact]
    public void ReadChanges_AfterRedefinition_AnswersTheWholeListFirst()
    {
        var (harness, panel) = Station();
        panel.Define(1, Items);
        panel.ReadChanges(1);
        panel.ReadChanges(1).Changes.Should().BeEmpty();

        panel.Define(1, new ReadItem(ProtocolArea.V, 400, 6));
        var first = panel.ReadChanges(1);
        var second = panel.ReadChanges(1);

        first.Full.Should().BeTrue("redefining cleared every list and its copy");
        first.Data.Should().Equal(harness.Reference.Memory.V.AsSpan(400, 6).ToArray());
        second.Changes.Should().BeEmpty();
    }

    [Fact]
    public void ReadChanges_AfterTheListsWereCleared_Answers07ThenWholeListOnceDefinedAgain()
    {
        var (harness, panel) = Station();
        panel.Define(1, Items);
        panel.Define(2, new ReadItem(ProtocolArea.V, 300, 12));
        panel.ReadChanges(1);
        panel.ReadChanges(2);

        // The longest READ reply reaches the stored descriptors: every list is cleared (invalidation 3).
        panel.Send(new ReadRequest(panel.Station, panel.NextSequence(), [new ReadItem(ProtocolArea.V, 500, ProtocolLimits.MaxReadData)]))
            .Should().BeOfType<ReadResponse>();
        var cleared = panel.Error(new ReadChangesRequest(panel.Station, panel.NextSequence(), 1, false));
        panel.Define(2, new ReadItem(ProtocolArea.V, 300, 12));
        var again = panel.ReadChanges(2);

        cleared.Should().Be(ProtocolError.ListNotDefined);
        again.Full.Should().BeTrue("the copies went with the lists");
        panel.ReadChanges(2).Changes.Should().BeEmpty();
        harness.Reference.Memory.V.AsSpan(300, 12).ToArray().Should().Equal(panel.Known(2));
    }

    /// <summary>
    /// Issue 23: a list ending in one of the last three bytes of its area. The comparison's double-word compare of a
    /// 4-byte chunk read 4 bytes at the list's byte whatever the chunk's length, past the area's end: the interpreter
    /// stopped the handler there and the station answered nothing ever after. The copy at the end of the copy area
    /// (the last V bytes) is the same case for the second pointer.
    /// </summary>
    [Theory]
    [InlineData(ProtocolArea.M, 29, 3)]
    [InlineData(ProtocolArea.M, 31, 1)]
    [InlineData(ProtocolArea.Q, 13, 3)]
    [InlineData(ProtocolArea.V, 8189, 2)]
    [InlineData(ProtocolArea.I, 15, 1)]
    public void ReadChanges_ListAtTheEndOfItsArea_AnswersNoPairsAndKeepsAnswering(ProtocolArea area, int offset, int length)
    {
        var (_, panel) = Station(copyBytes: length);
        panel.Define(1, new ReadItem(area, offset, length));
        panel.ReadChanges(1).Full.Should().BeTrue();

        var idle = panel.ReadChanges(1);
        var again = panel.ReadChanges(1);

        (idle.Full, idle.Changes.Length).Should().Be((false, 0), "nothing changed: K = 00, as the reference answers");
        again.Changes.Should().BeEmpty("the station still answers");
    }

    [Theory]
    [InlineData(1, 0x02, "F806")]
    [InlineData(1, 0x81, "F806")]
    [InlineData(0, 0x00, "F807")]
    [InlineData(5, 0x00, "F807")]
    [InlineData(3, 0x00, "F807")]
    public void ReadChanges_BadFlagsOrList_AnswersTheErrorLikeTheReference(byte list, byte flags, string cmdAndStatus)
    {
        var (_, panel) = Station();
        panel.Define(1, Items);

        var (stl, reference) = panel.Raw(new FreeportFrame(2, panel.NextSequence(), (byte)CommandCode.ReadChanges, [list, flags]));

        stl.Should().Be(reference);
        stl.Substring(5, 4).Replace('F', '8').Should().Be(cmdAndStatus.Replace('F', '8'), "CMD 88 and the status");
    }

    [Theory]
    [InlineData(1)]
    [InlineData(3)]
    public void ReadChanges_BodyNotFiveBytes_Answers04LikeTheReference(int payloadBytes)
    {
        var (_, panel) = Station();
        panel.Define(1, Items);

        var (stl, reference) = panel.Raw(new FreeportFrame(2, panel.NextSequence(), (byte)CommandCode.ReadChanges, [.. Enumerable.Repeat((byte)1, payloadBytes)]));

        stl.Should().Be(reference);
        stl.Substring(5, 4).Should().Be("8804");
    }

    private static (DifferentialHarness Harness, ChangesExchange Panel) Station(int copyBytes = HandlerDefaults.CopyBytes)
    {
        var options = new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2, CopyBytes = copyBytes };
        var harness = new DifferentialHarness(options, new Random(11));
        return (harness, new ChangesExchange(harness, 2));
    }

    private static byte[] Memory(DifferentialHarness harness) =>
        [.. Items.SelectMany(i => harness.Reference.Memory.Area(i.Area).AsSpan(i.Offset, i.Length).ToArray())];
}
