using System.Collections.Immutable;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// 05 DEFINE LIST, 06 READ LIST and 07 READ LIST FULL of the generated v3 handler against the reference model, byte for
/// byte, with a PC that applies every reply to what it knows of the list: the whole list first, then UNCHANGED,
/// CHANGES or the whole list again, and what the PC knows is always the memory's bytes.
/// </summary>
public sealed class V3ListTests
{
    private static readonly ReadItem[] Ranges =
    [
        new(ProtocolArea.I, 0, 3), new(ProtocolArea.Q, 0, 2), new(ProtocolArea.V, 100, 2), new(ProtocolArea.V, 104, 4),
        new(ProtocolArea.M, 0, 18), new(ProtocolArea.M, 29, 3), new(ProtocolArea.Q, 13, 3), new(ProtocolArea.V, 8189, 3),
        new(ProtocolArea.I, 14, 2), new(ProtocolArea.V, 400, 9),
    ];

    [Fact]
    public void ReadList_FirstWholeThenUnchanged_AndWhatThePcKnowsIsTheMemory()
    {
        var (station, pc) = Defined(Ranges);

        var first = pc.Read();
        var idle = pc.Read();

        first.Should().Be(ReplyStatus.Ok);
        idle.Should().Be(ReplyStatus.Unchanged);
        pc.Known.Should().Equal(Memory(station, pc));
    }

    [Fact]
    public void ReadList_AFewDoubleWordsChanged_AnswersTheirEntries()
    {
        var (station, pc) = Defined(Ranges);
        pc.Read();

        station.Poke(ProtocolArea.M, 31, (byte)~station.Reference.Memory.M[31]);
        station.Poke(ProtocolArea.V, 8191, (byte)~station.Reference.Memory.V[8191]);
        var changes = pc.Read();

        changes.Should().Be(ReplyStatus.Changes);
        pc.Known.Should().Equal(Memory(station, pc));
        pc.Read().Should().Be(ReplyStatus.Unchanged, "the copy moved on with the reply");
    }

    [Fact]
    public void ReadList_ManyChanged_AnswersTheWholeList_AndFullAlwaysDoes()
    {
        var (station, pc) = Defined(Ranges);
        pc.Read();

        foreach (var range in Ranges)
        {
            station.Poke(range.Area, range.Offset, [.. station.Reference.Memory.Area(range.Area).AsSpan(range.Offset, range.Length).ToArray().Select(b => (byte)~b)]);
        }

        var many = pc.Read();
        var full = pc.Read(full: true);

        (many, full).Should().Be((ReplyStatus.Ok, ReplyStatus.Ok));
        pc.Known.Should().Equal(Memory(station, pc));
    }

    [Fact]
    public void ReadList_TheLongestList_AnswersLikeTheReference()
    {
        var ranges = Enumerable.Range(0, 32).Select(i => new ReadItem(ProtocolArea.V, 1000 + (i * 6), 4)).ToArray();
        var (station, pc) = Defined(ranges);

        pc.Read().Should().Be(ReplyStatus.Ok);
        station.Poke(ProtocolArea.V, 1000, 0xA5);
        station.Poke(ProtocolArea.V, 1000 + (31 * 6) + 3, 0x5A);
        pc.Read().Should().Be(ReplyStatus.Changes);
        foreach (var i in Enumerable.Range(0, 26))
        {
            station.Poke(ProtocolArea.V, 1000 + (i * 6), (byte)i);
        }

        pc.Read().Should().Be(ReplyStatus.Ok, "26 changed slots do not fit as entries: the whole list");
        pc.Known.Should().Equal(Memory(station, pc));
    }

    [Fact]
    public void ReadList_AWindowByteOutsideItsItemChanged_AnEntryThatLeavesTheItemsBytes()
    {
        var (station, pc) = Defined([new ReadItem(ProtocolArea.V, 300, 1), new ReadItem(ProtocolArea.M, 30, 2)]);
        pc.Read();

        station.Poke(ProtocolArea.V, 302, (byte)~station.Reference.Memory.V[302]);
        var changes = pc.Read();

        changes.Should().Be(ReplyStatus.Changes, "slot 0's window is VB300-VB303");
        pc.Plan.Items[1].Should().Be(new ReadItem(ProtocolArea.M, 28, 4), "MB30-MB31 widened back so its window MB28-MB31 stays in M");
        pc.Known.Should().Equal(Memory(station, pc));
        pc.Read().Should().Be(ReplyStatus.Unchanged);
    }

    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    [InlineData(1, 3)]
    [InlineData(0, 2, 3)]
    public void ReadList_ChangesInChosenQuarters_AnswerTheirEntriesLikeTheReference(params int[] quarters)
    {
        var ranges = Enumerable.Range(0, 32).Select(i => new ReadItem(ProtocolArea.V, 2000 + (i * 4), 4)).ToArray();
        var (station, pc) = Defined(ranges);
        pc.Read().Should().Be(ReplyStatus.Ok);
        pc.Read().Should().Be(ReplyStatus.Unchanged);

        foreach (var quarter in quarters)
        {
            station.Poke(ProtocolArea.V, 2000 + (quarter * 32) + 5, (byte)(0x11 * (quarter + 1)));
        }

        pc.Read().Should().Be(ReplyStatus.Changes, "the comparison resumes at each quarter after one that differs");
        pc.Known.Should().Equal(Memory(station, pc));
        pc.Read().Should().Be(ReplyStatus.Unchanged);
    }

    [Theory]
    [InlineData("")]
    [InlineData("04000001")]
    [InlineData("04000001040000010400000104000001040000010400000104000001")]
    [InlineData("0400000104000001040000010400000104000001040000010400000104000001FF")]
    [InlineData("0400000504000001040000010400000104000001040000010400000104000001")]
    [InlineData("0400000104000001040000000400000104000001040000010400000104000001")]
    [InlineData("0400000104000001040000010700000104000001040000010400000104000001")]
    [InlineData("04000001040000010400000104000001040000010400000104FFF00104000001")]
    [InlineData("0400000104000001040000010400000104000001040000010400000105022601")]
    [InlineData("0400000104000001040000010400000104000001040000010400000100000001")]
    [InlineData("0400000104000001040000010400000104000001040000010400000103001F02")]
    [InlineData("0400000104000001040000010400000104000001040000010400000103001F01")]
    [InlineData("0400000104000001040000010400000104000001040000010400000102000D03")]
    public void DefineList_Refusals_AnswerTheFirstFailingCheckLikeTheReference_AndLeaveNoList(string payload)
    {
        var station = Station();
        var pc = new ListPc(station);
        Defined(station, pc, Ranges);

        pc.Raw(new Request(station.Station, 1, Command.DefineList, [.. Convert.FromHexString(payload)])).Should().NotBe(ReplyStatus.Ok);
        pc.Raw(Request.ReadList(station.Station, 2)).Should().Be(ReplyStatus.ListNotDefined);
    }

    [Fact]
    public void ReadList_NoListOrAPayload_AnswersLikeTheReference()
    {
        var station = Station();
        var pc = new ListPc(station);

        pc.Raw(Request.ReadList(station.Station, 1)).Should().Be(ReplyStatus.ListNotDefined);
        pc.Raw(Request.DefineList(station.Station, 2, Enumerable.Repeat(new ReadItem(ProtocolArea.V, 0, 1), 8))).Should().Be(ReplyStatus.Ok);
        pc.Raw(new Request(station.Station, 4, Command.ReadList, [0])).Should().Be(ReplyStatus.UnknownCommand, "READ LIST has no payload");
        pc.Raw(new Request(station.Station, 6, Command.ReadListFull, [1, 2])).Should().Be(ReplyStatus.UnknownCommand, "READ LIST FULL has no payload");
        pc.Raw(Request.ReadListFull(station.Station, 5)).Should().Be(ReplyStatus.Ok);
    }

    private static V3Station Station(int seed = 9) =>
        new(new HandlerOptions { Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2 }, new Random(seed));

    private static (V3Station, ListPc) Defined(ReadItem[] ranges)
    {
        var station = Station();
        var pc = new ListPc(station);
        Defined(station, pc, ranges);
        return (station, pc);
    }

    private static void Defined(V3Station station, ListPc pc, ReadItem[] ranges)
    {
        ListPlan.TryMake(ranges, station.Reference.Setup.Shape, ListPlan.AreaBytesOf(station.Reference.Setup.Cpu), out var plan).Should().BeTrue();
        pc.Raw(plan.Request(station.Station, pc.NextSequence())).Should().Be(ReplyStatus.Ok);
        pc.Plan = plan;
    }

    /// <summary>The list data as the memory holds it now: the plan's items' bytes (the ranges, then the IB12 fillers).</summary>
    private static byte[] Memory(V3Station station, ListPc pc) =>
        [.. pc.Plan.Items.SelectMany(r => station.Reference.Memory.Area(r.Area).AsSpan(r.Offset, r.Length).ToArray())];

    /// <summary>The PC's side: every exchange compared with the reference; list replies applied to what it knows.</summary>
    private sealed class ListPc(V3Station station)
    {
        private byte _sequence;

        public ListPlan Plan { get; set; } = null!;

        public ImmutableArray<byte> Known { get; private set; } = [];

        public byte NextSequence() => _sequence = (byte)((_sequence + 1) % Limits.SequenceCount);

        public ReplyStatus Raw(Request request)
        {
            var sent = Codec.Encode(request);
            var (stl, reference) = station.Exchange(sent);
            Convert.ToHexString(stl).Should().Be(Convert.ToHexString(reference), $"the handler answers {Convert.ToHexString(sent)} like the reference");
            Codec.TryDecodeReplyTo(stl, sent, out var reply, out var error).Should().BeTrue(error.ToString());
            return reply.Status;
        }

        public ReplyStatus Read(bool full = false)
        {
            var sent = Codec.Encode(full ? Request.ReadListFull(station.Station, NextSequence()) : Request.ReadList(station.Station, NextSequence()));
            var (stl, reference) = station.Exchange(sent);
            Convert.ToHexString(stl).Should().Be(Convert.ToHexString(reference));
            Codec.TryDecodeReplyTo(stl, sent, out var reply, out _).Should().BeTrue();
            ListReply.TryRead(reply, Plan, out var list).Should().BeTrue($"{reply.Status} with {reply.Payload.Length} bytes is a list reply");
            list.TryApply(Known.AsSpan(), Plan, out var now).Should().BeTrue();
            Known = now;
            return reply.Status;
        }
    }
}
