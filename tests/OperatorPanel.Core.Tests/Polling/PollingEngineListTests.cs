using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using Serilog.Events;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>Stored lists: defined once per frame, polled with READ CHANGES, redefined on 07, plain READ when refused.</summary>
public sealed class PollingEngineListTests
{
    private readonly PollingTestClock _clock = new();
    private readonly PollingLogSink _log = new();
    private readonly FakePlcLink _link;

    public PollingEngineListTests() => _link = new FakePlcLink(_clock);

    [Fact]
    public async Task RunCycle_TwoStations_DefinesEachListOnceThenPollsWithReadChanges()
    {
        _link.Set(One, ProtocolArea.V, 10, 0x12, 0x34);
        _link.Set(Two, ProtocolArea.M, 3, 0x08);
        var engine = Engine([Item(One, "VW10"), Item(Two, "M3.3")]);

        await engine.RunCycleAsync(CancellationToken.None);
        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Select(r => (r.Station.Address, r.Command)).Should().Equal(
            (1, CommandCode.DefineList), (1, CommandCode.ReadChanges), (2, CommandCode.DefineList), (2, CommandCode.ReadChanges),
            (1, CommandCode.ReadChanges), (2, CommandCode.ReadChanges));
        _link.Requests.OfType<DefineListRequest>().Select(d => (d.List, d.Items.Single()))
            .Should().Equal((1, new ReadItem(ProtocolArea.V, 10, 2)), (1, new ReadItem(ProtocolArea.M, 3, 1)));
        Value(engine, One, "VW10").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x12 && v.Raw[1] == 0x34);
        Value(engine, Two, "M3.3").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 1);
    }

    [Fact]
    public async Task RunCycle_StationLostItsLists_RedefinesAndReadsAgainInTheSameCycle()
    {
        var engine = Engine(Items(One, "VB0"));
        await engine.RunCycleAsync(CancellationToken.None);
        _link.ClearLists(One);
        _link.Set(One, ProtocolArea.V, 0, 0x5A);

        var result = await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Skip(2).Select(r => r.Command).Should().Equal(CommandCode.ReadChanges, CommandCode.DefineList, CommandCode.DefineList, CommandCode.ReadChanges);
        _link.Requests.OfType<DefineListRequest>().Skip(1).Select(d => d.Items[0].Offset).Should().Equal([ushort.MaxValue, 0], "the tail is cleared before the list is defined again");
        _link.Requests.OfType<ReadChangesRequest>().Last().Full.Should().BeTrue("a list defined again has no valid copy");
        result.Should().Match<PollResult>(r => r.FramesSent == 1 && r.FramesFailed == 0);
        Value(engine, One, "VB0").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x5A);
    }

    [Fact]
    public async Task RunCycle_DefineRepeatedAfterALostReplyClearedTheOtherList_ClearsTheTailAndDefinesBothAgain()
    {
        var items = Enumerable.Range(0, 26).Select(i => Item(One, $"VB{i * 10}")).ToArray();
        var engine = Engine(items);
        engine.Plan.ListCount.Should().Be(2);
        await engine.RunCycleAsync(CancellationToken.None);

        // What the link's resend of a DEFINE 2 whose reply was lost leaves: list 2 defined again, list 1 cleared by it.
        var list2 = _link.Requests.OfType<DefineListRequest>().Single(d => d.List == 2);
        _link.ClearLists(One);
        await _link.ExchangeAsync(list2, CancellationToken.None);
        var before = _link.Requests.Count;

        var result = await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Skip(before).OfType<DefineListRequest>().Select(d => d.Items[0].Offset == ushort.MaxValue ? $"clear {d.List}" : $"define {d.List}")
            .Should().Equal("clear 1", "clear 2", "define 1", "define 2");
        result.FramesFailed.Should().Be(0);
        var after = _link.Requests.Count;
        await engine.RunCycleAsync(CancellationToken.None);
        _link.Requests.Skip(after).Should().NotContain(r => r is DefineListRequest || r is ReadRequest, "both lists are stored and polled again");
    }

    [Fact]
    public async Task RunCycle_DefineRefused_ReadsThatFrameWithPlainReadAndLogsOnce()
    {
        _link.RefusesLists.Add(One);
        _link.Set(One, ProtocolArea.V, 0, 0x21);
        var engine = Engine(Items(One, "VB0"));

        await engine.RunCycleAsync(CancellationToken.None);
        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Select(r => r.Command).Should().Equal(CommandCode.DefineList, CommandCode.Read, CommandCode.Read);
        Value(engine, One, "VB0").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x21);
        _log.Events.Where(e => e.Level == LogEventLevel.Warning && e.MessageTemplate.Text.Contains("DEFINE LIST", StringComparison.Ordinal))
            .Should().ContainSingle();
    }

    [Fact]
    public async Task RunCycle_ReadListsSwitchedOff_UsesPlainReadOnly()
    {
        var engine = new PollingEngine(_link, PollPlanner.Build(Items(One, "VB0")), _clock, options: new PollingOptions { UseReadLists = false });

        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Should().ContainSingle().Which.Should().BeOfType<ReadRequest>();
    }

    [Fact]
    public void ReadListAssignment_ListIdsOfThePlansFrames()
    {
        var plan = PollPlan.Empty with
        {
            Frames =
            [
                new PollFrame(One, [new ReadItem(ProtocolArea.V, 0, 4)]) { List = 1 },
                new PollFrame(One, [new ReadItem(ProtocolArea.V, 600, 100)]),
                new PollFrame(Two, [new ReadItem(ProtocolArea.M, 0, 2)]) { List = 1 },
            ],
        };

        ReadListAssignment.For(plan).Should().Equal(new Dictionary<int, int> { [0] = 1, [2] = 1 });
    }

    private static PolledValue Value(PollingEngine engine, Core.Addressing.Station station, string address)
    {
        engine.TryGetValue(station, PlcAddress.Parse(address), out var value).Should().BeTrue();
        return value;
    }

    private PollingEngine Engine(IEnumerable<WatchedItem> items) =>
        new(_link, PollPlanner.Build(items), _clock, _log.CreateLogger());
}
