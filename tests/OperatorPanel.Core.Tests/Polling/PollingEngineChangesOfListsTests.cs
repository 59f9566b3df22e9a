using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using Serilog.Events;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>
/// 09 READ CHANGES OF LISTS (docs/protocol-v2.md section 2, its PC rules 1-5) on a station with two stored lists: 26 one-byte
/// items VB0, VB10 .. VB250, which one list cannot hold.
/// </summary>
public sealed class PollingEngineChangesOfListsTests
{
    private const byte ChangesOfListsHandler = HandlerIdentity.CopiesFeature | HandlerIdentity.ChangesOfListsFeature;

    private readonly PollingTestClock _clock = new();
    private readonly PollingLogSink _log = new();
    private readonly FakePlcLink _link;

    public PollingEngineChangesOfListsTests() => _link = new FakePlcLink(_clock);

    [Fact]
    public async Task RunCycle_TwoListsInStep_OneReadChangesOfListsReadsBoth()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        Sent().Should().Equal("define 1", "define 2", "08 1 full", "08 2 full");

        var idle = await CycleAsync(engine);

        idle.Requests.Should().Equal("09 1+2");
        idle.Result.Should().Match<PollResult>(r => r.FramesSent == 2 && r.FramesFailed == 0 && r.ValuesChanged == 0);
        Value(engine, "VB250").Quality.Should().Be(ValueQuality.Good);
    }

    [Fact]
    public async Task RunCycle_PairsInBothLists_EveryValueIsRightAndGood()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        var (first, second) = (ItemsOf(engine, 1)[0], ItemsOf(engine, 2)[^1]);
        _link.Set(One, ProtocolArea.V, first.Offset, 0x11);
        _link.Set(One, ProtocolArea.V, second.Offset, 0x22);
        _clock.Advance(TimeSpan.FromSeconds(1));

        var cycle = await CycleAsync(engine);

        cycle.Requests.Should().Equal("09 1+2");
        Value(engine, $"VB{first.Offset}").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x11);
        Value(engine, $"VB{second.Offset}").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x22);
        Value(engine, $"VB{ItemsOf(engine, 2)[0].Offset}").Should().Match<PolledValue>(v =>
            v.Quality == ValueQuality.Good && v.Raw[0] == 0 && v.Timestamp == _clock.GetUtcNow());
        cycle.Result.ValuesChanged.Should().Be(2);
    }

    [Fact]
    public async Task RunCycle_OneListDueFull_ItIsReadWith08FullAndTheOtherGoesIn09()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        _clock.Advance(TimeSpan.FromSeconds(5));
        ChangeEveryByteOf(engine, 2, 0x40);

        // 2K >= D: list 2 answers REREAD and is read FULL at 5 s, so its 10-second guard runs 5 s behind list 1's.
        (await CycleAsync(engine)).Requests.Should().Equal("09 1+2", "08 2 full");
        _clock.Advance(TimeSpan.FromSeconds(5));
        _link.Set(One, ProtocolArea.V, ItemsOf(engine, 2)[0].Offset, 0x41);

        var cycle = await CycleAsync(engine);

        cycle.Requests.Should().Equal("09 2", "08 1 full");
        Value(engine, $"VB{ItemsOf(engine, 2)[0].Offset}").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x41);
    }

    [Fact]
    public async Task RunCycle_FullReadIntervalPassedForBoth_BothAreReadWith08FullAndNo09IsSent()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        _clock.Advance(TimeSpan.FromSeconds(9.9));
        (await CycleAsync(engine)).Requests.Should().Equal("09 1+2");
        _clock.Advance(TimeSpan.FromSeconds(0.1));

        var cycle = await CycleAsync(engine);

        cycle.Requests.Should().Equal("08 1 full", "08 2 full");
    }

    [Fact]
    public async Task RunCycle_ReplyTo09Lost_BothListsAreReadWith08FullInTheSameCycleAndThe09IsNotRepeated()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        var changed = ItemsOf(engine, 1)[0].Offset;
        _link.Set(One, ProtocolArea.V, changed, 0x7E);

        // The PLC answers the change (its copy of list 1 now holds 7E) but the reply is lost: a 09 again would say "no change".
        _link.LosesReplyTo = r => r is ReadChangesOfListsRequest;
        var lost = await CycleAsync(engine);
        _link.LosesReplyTo = null;
        var after = await CycleAsync(engine);

        lost.Requests.Should().Equal("09 1+2", "08 1 full", "08 2 full");
        lost.Result.FramesFailed.Should().Be(0);
        Value(engine, $"VB{changed}").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x7E);
        after.Requests.Should().Equal("09 1+2");
    }

    [Fact]
    public async Task RunCycle_09AndItsFullsLost_ValuesGoStaleAndTheNextCycleReadsBothWith08Full()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        _link.LosesReplyTo = r => r is ReadChangesOfListsRequest or ReadChangesRequest;
        var lost = await CycleAsync(engine);
        _link.LosesReplyTo = null;
        _link.Set(One, ProtocolArea.V, 250, 0x03);

        var next = await CycleAsync(engine);

        // The first lost FULL takes the station offline: list 2 is skipped (not attempted), its values go Stale with list 1's.
        lost.Requests.Should().Equal("09 1+2", "08 1 full");
        lost.Result.Should().Match<PollResult>(r => r.FramesSent == 1 && r.FramesFailed == 1);
        next.Requests.Should().Equal("08 1 full", "08 2 full");
        next.Result.FramesFailed.Should().Be(0);
        Value(engine, "VB250").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x03);
    }

    [Fact]
    public async Task RunCycle_09AndItsFullsLost_EveryValueIsStaleMeanwhile()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        _link.LosesReplyTo = r => r is ReadChangesOfListsRequest or ReadChangesRequest;

        await engine.RunCycleAsync(CancellationToken.None);

        engine.Plan.Values.Select(v => Value(engine, v.Item.Address.ToString()).Quality).Should().OnlyContain(q => q == ValueQuality.Stale);
    }

    [Fact]
    public async Task RunCycle_ListAnsweredReread_ItIsReadWith08FullInTheSameCycleAndEveryValueIsComplete()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        ChangeEveryByteOf(engine, 2, 0x55);
        var first = ItemsOf(engine, 1)[0].Offset;
        _link.Set(One, ProtocolArea.V, first, 0x66);

        var cycle = await CycleAsync(engine);

        cycle.Requests.Should().Equal("09 1+2", "08 2 full");
        cycle.Result.Should().Match<PollResult>(r => r.FramesSent == 2 && r.FramesFailed == 0);
        Value(engine, $"VB{first}").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x66);
        ItemsOf(engine, 2).Select(i => Value(engine, $"VB{i.Offset}")).Should()
            .OnlyContain(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x55);
        (await CycleAsync(engine)).Requests.Should().Equal("09 1+2");
    }

    [Fact]
    public async Task RunCycle_09IndexPastTheListsData_DropsTheWholeReplyAndReadsEveryListOfTheMaskWith08Full()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        var last = ItemsOf(engine, 2)[^1].Offset;
        _link.Set(One, ProtocolArea.V, last, 0x99);

        // List 1 holds fewer than 200 bytes; list 2's entry is right but the reply is dropped whole (rule 4).
        _link.Tamper = (request, reply) => reply is ReadChangesOfListsResponse lists
            ? lists with { Lists = lists.Lists.SetItem(0, ListChanges.Pairs(1, [new ChangedByte(200, 0x01)])) }
            : reply;
        var cycle = await CycleAsync(engine);

        cycle.Requests.Should().Equal("09 1+2", "08 1 full", "08 2 full");
        cycle.Result.FramesFailed.Should().Be(0);
        Value(engine, $"VB{last}").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x99);
        engine.Plan.Values.Select(v => Value(engine, v.Item.Address.ToString()).Raw[0]).Should().NotContain(0x01);
        _log.Events.Should().Contain(e => e.Level == LogEventLevel.Warning && e.RenderMessage(null).Contains("READ CHANGES OF LISTS 1, 2", StringComparison.Ordinal));
    }

    [Fact]
    public async Task RunCycle_ListsRereadWithNothingChanged_ReadListUntilTheNextPeriodicFull()
    {
        // A handler whose lists got no copy answers every 09 entry REREAD: the FULL that follows shows nothing changed.
        _link.KeepsNoCopies.Add(One);
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);

        var reread = await CycleAsync(engine);
        _clock.Advance(TimeSpan.FromSeconds(5));
        var spell = await CycleAsync(engine);
        _clock.Advance(TimeSpan.FromSeconds(5));
        var periodic = await CycleAsync(engine);

        reread.Requests.Should().Equal("09 1+2", "08 1 full", "08 2 full");
        spell.Requests.Should().Equal("06 1", "06 2");
        periodic.Requests.Should().Equal("08 1 full", "08 2 full");
        Value(engine, "VB250").Quality.Should().Be(ValueQuality.Good);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public async Task RunCycle_HandlerWithoutFeatureBit2_ReadsEachListWith08(bool identified)
    {
        var engine = TwoListEngine(identity: identified ? HandlerIdentity.CopiesFeature : null);
        await engine.RunCycleAsync(CancellationToken.None);

        var idle = await CycleAsync(engine);

        idle.Requests.Should().Equal("08 1", "08 2");
    }

    [Fact]
    public async Task RunCycle_IdentityLosesFeatureBit2_BackTo08()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        engine.NoteIdentity(Identity(HandlerIdentity.CopiesFeature));

        var idle = await CycleAsync(engine);

        idle.Requests.Should().Equal("08 1", "08 2");
    }

    [Fact]
    public async Task RunCycle_HandlerAnswers09WithUnknownCommand_ReadsTheListsFullThenWith08Only()
    {
        _link.LacksChangesOfLists.Add(One);
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);

        var refused = await CycleAsync(engine);
        var after = await CycleAsync(engine);

        refused.Requests.Should().Equal("09 1+2", "08 1 full", "08 2 full");
        refused.Result.FramesFailed.Should().Be(0);
        after.Requests.Should().Equal("08 1", "08 2");
        _log.Events.Should().ContainSingle(e => e.Level == LogEventLevel.Warning && e.RenderMessage(null).Contains("refused READ CHANGES OF LISTS", StringComparison.Ordinal));
    }

    [Fact]
    public async Task RunCycle_09AnsweredListNotDefined_DefinesTheListsAgainAndReadsThemFull()
    {
        var engine = TwoListEngine();
        await engine.RunCycleAsync(CancellationToken.None);
        _link.ClearLists(One);

        var cycle = await CycleAsync(engine);

        cycle.Requests.Should().Equal("09 1+2", "clear 1", "clear 2", "define 1", "define 2", "08 1 full", "08 2 full");
        cycle.Result.FramesFailed.Should().Be(0);
    }

    [Fact]
    public async Task RunCycle_TwoStationsOnlyOneWithFeatureBit2_EachIsReadTheWayItsHandlerAnswers()
    {
        var engine = new PollingEngine(_link, PollPlanner.Build([.. Items(One, "VB0", "VW2"), .. Items(Two, "VB0", "VW2")]), _clock);
        engine.NoteIdentity(Identity(ChangesOfListsHandler));
        engine.NoteIdentity(Identity(HandlerIdentity.CopiesFeature) with { Station = Two });
        await engine.RunCycleAsync(CancellationToken.None);
        var before = _link.Requests.Count;

        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Skip(before).Select(r => $"{r.Station.Address}: {Describe(r)}").Should().Equal("1: 09 1", "2: 08 1");
    }

    [Fact]
    public async Task RunCycle_StationWithOneList_IdleCycleIsOne09()
    {
        var engine = new PollingEngine(_link, PollPlanner.Build(Items(One, "VB0", "VW2")), _clock);
        engine.NoteIdentity(Identity(ChangesOfListsHandler));
        await engine.RunCycleAsync(CancellationToken.None);

        var idle = await CycleAsync(engine);

        // docs/protocol-v2.md 09 rule 5: 14 + 20 = 34 characters, 2 less than an idle 08.
        idle.Requests.Should().Equal("09 1");
    }

    private static IdentifyResponse Identity(byte features) =>
        new(One, 1, 2, 1, 5, 1, 0x0E, 116, 5, 0x90, 1, 3, 2, 5, 0, 9812, 428, features, 120);

    private static PolledValue Value(PollingEngine engine, string address)
    {
        engine.TryGetValue(One, PlcAddress.Parse(address), out var value).Should().BeTrue();
        return value;
    }

    private static System.Collections.Immutable.ImmutableArray<ReadItem> ItemsOf(PollingEngine engine, int list) => engine.Plan.Frames.Single(f => f.List == list).Items;

    private static string Describe(PlcRequest request) => request switch
    {
        DefineListRequest define when define.Items[0].Offset == ushort.MaxValue => $"clear {define.List}",
        DefineListRequest define => $"define {define.List}",
        ReadChangesRequest changes => $"08 {changes.List}{(changes.Full ? " full" : string.Empty)}",
        ReadChangesOfListsRequest lists => $"09 {string.Join("+", lists.Lists)}",
        ReadListRequest list => $"06 {list.List}",
        _ => throw new InvalidOperationException($"the engine sent {request.Command}, which these tests do not expect"),
    };

    private void ChangeEveryByteOf(PollingEngine engine, int list, byte value)
    {
        foreach (var item in ItemsOf(engine, list))
        {
            _link.Set(One, item.Area, item.Offset, Enumerable.Repeat(value, item.Length).ToArray());
        }
    }

    private List<string> Sent() => [.. _link.Requests.Select(Describe)];

    /// <summary>One cycle, with the requests it sent.</summary>
    private async Task<(PollResult Result, List<string> Requests)> CycleAsync(PollingEngine engine)
    {
        var before = _link.Requests.Count;
        var result = await engine.RunCycleAsync(CancellationToken.None);
        return (result, Sent().Skip(before).ToList());
    }

    private PollingEngine TwoListEngine(byte? identity = ChangesOfListsHandler)
    {
        var engine = new PollingEngine(_link, PollPlanner.Build(Enumerable.Range(0, 26).Select(i => Item(One, $"VB{i * 10}"))), _clock, _log.CreateLogger());
        engine.Plan.ListCount.Should().Be(2, "26 one-byte items: 4 x 26 + 20 + 2 x 26 > 255 for one list");
        if (identity is { } features)
        {
            engine.NoteIdentity(Identity(features));
        }

        return engine;
    }
}
