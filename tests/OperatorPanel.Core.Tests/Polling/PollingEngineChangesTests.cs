using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>READ CHANGES (docs/protocol-v2.md, PC rules): FULL first, after a lost reply and every 10 s; pairs applied; READ LIST without copies.</summary>
public sealed class PollingEngineChangesTests
{
    private readonly PollingTestClock _clock = new();
    private readonly FakePlcLink _link;

    public PollingEngineChangesTests() => _link = new FakePlcLink(_clock);

    [Fact]
    public async Task RunCycle_OneByteChanged_OnlyThatByteTravelsAndEveryValueStaysGood()
    {
        _link.Set(One, ProtocolArea.V, 10, 0x12, 0x34, 0x56);
        var engine = Engine(Items(One, "VW10", "VB12"));
        await engine.RunCycleAsync(CancellationToken.None);
        _link.Set(One, ProtocolArea.V, 12, 0x99);
        _clock.Advance(TimeSpan.FromSeconds(1));

        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.OfType<ReadChangesRequest>().Select(r => r.Full).Should().Equal(true, false);
        Value(engine, "VB12").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x99);
        Value(engine, "VW10").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x12 && v.Raw[1] == 0x34
            && v.Timestamp == _clock.GetUtcNow());
    }

    [Fact]
    public async Task RunCycle_NothingChanged_ValuesStayGoodAndNothingIsPublished()
    {
        _link.Set(One, ProtocolArea.M, 0, 0x05);
        var engine = Engine(Items(One, "M0.0", "M0.1", "M0.2"));
        await engine.RunCycleAsync(CancellationToken.None);

        var idle = await engine.RunCycleAsync(CancellationToken.None);

        idle.Should().Match<PollResult>(r => r.FramesFailed == 0 && r.ValuesChanged == 0);
        Value(engine, "M0.0").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 1);
        Value(engine, "M0.1").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0);
    }

    [Fact]
    public async Task RunCycle_ReplyToChangesLost_AsksFullAtOnceAndMissesNoChange()
    {
        _link.Set(One, ProtocolArea.V, 0, 0x01);
        var engine = Engine(Items(One, "VB0"));
        await engine.RunCycleAsync(CancellationToken.None);
        _link.Set(One, ProtocolArea.V, 0, 0x02);

        // The PLC answers the change (its copy now holds 02) but the reply is lost: a repeat without FULL would say "no change".
        _link.LosesReplyTo = r => r is ReadChangesRequest { Full: false };
        var result = await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.OfType<ReadChangesRequest>().Select(r => r.Full).Should().Equal(true, false, true);
        result.FramesFailed.Should().Be(0);
        Value(engine, "VB0").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x02);
    }

    [Fact]
    public async Task RunCycle_FullReplyLostToo_ValueGoesStaleAndTheNextCycleAsksFull()
    {
        _link.Set(One, ProtocolArea.V, 0, 0x01);
        var engine = Engine(Items(One, "VB0"));
        await engine.RunCycleAsync(CancellationToken.None);
        _link.LosesReplyTo = r => r is ReadChangesRequest;
        await engine.RunCycleAsync(CancellationToken.None);
        Value(engine, "VB0").Quality.Should().Be(ValueQuality.Stale);
        _link.LosesReplyTo = null;
        _link.Set(One, ProtocolArea.V, 0, 0x03);

        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.OfType<ReadChangesRequest>().Select(r => r.Full).Should().Equal(true, false, true, true);
        Value(engine, "VB0").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x03);
    }

    [Fact]
    public async Task RunCycle_FullReadIntervalPassed_AsksFullAgain()
    {
        var engine = Engine(Items(One, "VB0"), new PollingOptions { FullReadInterval = TimeSpan.FromSeconds(10) });
        await engine.RunCycleAsync(CancellationToken.None);
        _clock.Advance(TimeSpan.FromSeconds(9.9));
        await engine.RunCycleAsync(CancellationToken.None);
        _clock.Advance(TimeSpan.FromSeconds(0.1));

        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.OfType<ReadChangesRequest>().Select(r => r.Full).Should().Equal(true, false, true);
    }

    [Fact]
    public async Task RunCycle_HandlerWithoutCopies_ReadsItsListsWithReadList()
    {
        var engine = Engine(Items(One, "VB0"));
        engine.NoteIdentity(Identity(One, features: 0x00, copyBytes: 0));

        await engine.RunCycleAsync(CancellationToken.None);
        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Select(r => r.Command).Should().Equal(CommandCode.DefineList, CommandCode.ReadList, CommandCode.ReadList);
    }

    [Fact]
    public async Task RunCycle_ListAnsweredFullUnasked_ReadListUntilTheNextPeriodicFull()
    {
        _link.KeepsNoCopies.Add(One);
        var engine = Engine(Items(One, "VB0"));
        await engine.RunCycleAsync(CancellationToken.None);
        await engine.RunCycleAsync(CancellationToken.None);
        _clock.Advance(TimeSpan.FromSeconds(5));
        await engine.RunCycleAsync(CancellationToken.None);
        _clock.Advance(TimeSpan.FromSeconds(5));

        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Skip(1).Select(r => r is ReadChangesRequest c ? (c.Full ? "changes full" : "changes") : r.Command.ToString()).Should().Equal(
            "changes full", "changes", "ReadList", "changes full");
    }

    [Fact]
    public async Task RunCycle_ReadChangesSwitchedOff_PollsWithReadList()
    {
        var engine = Engine(Items(One, "VB0"), new PollingOptions { UseReadChanges = false });

        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Select(r => r.Command).Should().Equal(CommandCode.DefineList, CommandCode.ReadList);
    }

    [Fact]
    public async Task RunCycle_StationLostItsLists_DefinesAllItsListsAgainInIdOrder()
    {
        var items = Enumerable.Range(0, 26).Select(i => Item(One, $"VB{i * 10}")).ToArray();
        var engine = Engine(items);
        engine.Plan.ListCount.Should().Be(2, "26 one-byte items: 4 x 26 + 20 + 2 x 26 > 255 for one list");
        await engine.RunCycleAsync(CancellationToken.None);
        _link.ClearLists(One);
        var before = _link.Requests.Count;

        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Skip(before).Select(r => r switch
        {
            DefineListRequest d when d.Items[0].Offset == ushort.MaxValue => $"clear {d.List}",
            DefineListRequest d => $"define {d.List}",
            ReadChangesRequest c => $"changes {c.List}{(c.Full ? " full" : string.Empty)}",
            _ => r.Command.ToString(),
        }).Should().Equal("changes 1", "clear 1", "clear 2", "define 1", "define 2", "changes 1 full", "changes 2 full");
    }

    private static IdentifyResponse Identity(Station station, byte features, byte copyBytes) =>
        new(station, 1, 2, 1, 6, 2, 0x0F, 116, 5, 0, 1, 3, 2, 5, 0, 9900, 292, features, copyBytes);

    private static PolledValue Value(PollingEngine engine, string address)
    {
        engine.TryGetValue(One, PlcAddress.Parse(address), out var value).Should().BeTrue();
        return value;
    }

    private PollingEngine Engine(IEnumerable<WatchedItem> items, PollingOptions? options = null) =>
        new(_link, PollPlanner.Build(items), _clock, options: options);
}
