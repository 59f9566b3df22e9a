using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using Serilog.Events;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>One cycle at a time (RunCycleAsync): values, qualities, station states, resilience.</summary>
public sealed class PollingEngineTests
{
    private readonly PollingTestClock _clock = new();
    private readonly PollingLogSink _log = new();
    private readonly FakePlcLink _link;
    private readonly List<IReadOnlyList<ValueChange>> _batches = [];

    public PollingEngineTests() => _link = new FakePlcLink(_clock);

    [Fact]
    public async Task RunCycle_FirstRead_PublishesEveryValueOnceWithClockTimestamp()
    {
        _link.Set(One, ProtocolArea.V, 10, 0x12, 0x34);
        _link.Set(One, ProtocolArea.Q, 0, 0b0000_0100);
        var engine = Engine(Items(One, "VW10", "Q0.2"));
        _clock.Advance(TimeSpan.FromSeconds(3));

        await engine.RunCycleAsync(CancellationToken.None);

        _batches.Should().ContainSingle();
        _batches[0].Select(c => (c.Address.ToString(), Hex(c.Current), c.Current.Quality, c.Current.Timestamp, c.Previous.Quality))
            .Should().BeEquivalentTo(new[]
            {
                ("Q0.2", "01", ValueQuality.Good, PollingTestClock.Start.AddSeconds(3), ValueQuality.Bad),
                ("VW10", "1234", ValueQuality.Good, PollingTestClock.Start.AddSeconds(3), ValueQuality.Bad),
            });
    }

    [Fact]
    public async Task RunCycle_OneValueChanges_PublishesOnlyThatValue()
    {
        var engine = Engine(Items(One, "VB0", "VB1", "M0.1"));
        await engine.RunCycleAsync(CancellationToken.None);
        await engine.RunCycleAsync(CancellationToken.None);
        _link.Set(One, ProtocolArea.V, 1, 0x7F);
        _link.Set(One, ProtocolArea.M, 0, 0b1111_1101); // every bit of MB0 but M0.1
        _clock.Advance(TimeSpan.FromSeconds(1));

        await engine.RunCycleAsync(CancellationToken.None);

        _batches.Should().HaveCount(2, "the second cycle changed nothing and published nothing");
        _batches[1].Should().ContainSingle().Which.Should().Match<ValueChange>(c =>
            c.Address == PlcAddress.Parse("VB1") && c.Current.Raw[0] == 0x7F && c.Previous.Raw[0] == 0 && c.Current.Timestamp == PollingTestClock.Start.AddSeconds(1));
    }

    [Fact]
    public async Task RunCycle_StationStopsAnswering_ValuesGoStaleKeepingValueThenRecover()
    {
        _link.Set(One, ProtocolArea.V, 0, 0x2A);
        var engine = Engine(Items(One, "VB0"));
        await engine.RunCycleAsync(CancellationToken.None);
        _clock.Advance(TimeSpan.FromSeconds(1));
        _link.Fail(One, new PlcCommunicationException(PlcErrorKind.NoAnswer, One, "no answer after 3 tries"));

        await engine.RunCycleAsync(CancellationToken.None);
        await engine.RunCycleAsync(CancellationToken.None);

        engine.TryGetValue(One, PlcAddress.Parse("VB0"), out var stale).Should().BeTrue();
        stale.Should().Match<PolledValue>(v => v.Quality == ValueQuality.Stale && v.Raw[0] == 0x2A && v.Timestamp == PollingTestClock.Start);
        stale.Error.Should().Be("NoAnswer: no answer after 3 tries");
        engine.GetStationStatus(One).Should().Match<StationStatus>(s => s.State == StationState.Offline && s.ConsecutiveFailures == 2);
        _batches.Select(b => b.Single().Current.Quality).Should().Equal(ValueQuality.Good, ValueQuality.Stale);

        _link.Fail(One, null);
        _link.Set(One, ProtocolArea.V, 0, 0x2B);
        await engine.RunCycleAsync(CancellationToken.None);

        engine.TryGetValue(One, PlcAddress.Parse("VB0"), out var recovered).Should().BeTrue();
        recovered.Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x2B && v.Error == null);
        engine.GetStationStatus(One).Should().Match<StationStatus>(s => s.State == StationState.Online && s.ConsecutiveFailures == 0);
    }

    [Fact]
    public async Task RunCycle_NeverReadAndNoAnswer_ValueStaysBadWithTheError()
    {
        _link.Fail(One, new PlcCommunicationException(PlcErrorKind.Timeout, One, "timeout after 120 ms"));
        var engine = Engine(Items(One, "IB0"));

        await engine.RunCycleAsync(CancellationToken.None);

        engine.TryGetValue(One, PlcAddress.Parse("IB0"), out var value).Should().BeTrue();
        value.Should().Match<PolledValue>(v => v.Quality == ValueQuality.Bad && !v.HasValue && v.Error == "Timeout: timeout after 120 ms");
        _batches.Should().BeEmpty("Bad stays Bad: nothing changed");
    }

    [Fact]
    public async Task RunCycle_StationRefusesTheRead_ValuesGoBadAndStationStaysOnline()
    {
        var engine = Engine(Items(One, "VB0", "MB3"));
        await engine.RunCycleAsync(CancellationToken.None);
        _link.Refuse(One, ProtocolError.AddressOutOfRange);

        var result = await engine.RunCycleAsync(CancellationToken.None);

        result.FramesFailed.Should().Be(1);
        _batches[1].Select(c => (c.Address.ToString(), c.Current.Quality, c.Current.Error)).Should().BeEquivalentTo(new[]
        {
            ("MB3", ValueQuality.Bad, "station 1 refused READ M3+1, V0+1: AddressOutOfRange"),
            ("VB0", ValueQuality.Bad, "station 1 refused READ M3+1, V0+1: AddressOutOfRange"),
        });
        engine.GetStationStatus(One).State.Should().Be(StationState.Online);
    }

    [Fact]
    public async Task RunCycle_LinkThrowsUnexpectedException_OtherStationPolledAndSameStationRecovers()
    {
        _link.Set(Two, ProtocolArea.V, 0, 0x05);
        var engine = Engine([Item(One, "VB0"), Item(Two, "VB0")]);
        _link.Fail(One, new InvalidOperationException("driver bug"));

        var broken = await engine.RunCycleAsync(CancellationToken.None);

        broken.Should().Match<PollResult>(r => r.FramesSent == 2 && r.FramesFailed == 1);
        engine.TryGetValue(Two, PlcAddress.Parse("VB0"), out var other).Should().BeTrue();
        other.Quality.Should().Be(ValueQuality.Good);
        engine.GetStationStatus(One).Should().Match<StationStatus>(s =>
            s.State == StationState.Offline && s.LastError == "link error (InvalidOperationException): driver bug");
        _log.Events.Should().Contain(e => e.Level == LogEventLevel.Error && e.Exception is InvalidOperationException);

        _link.Fail(One, null);
        _clock.Advance(new PollingOptions().OfflineRetryInterval);
        await engine.RunCycleAsync(CancellationToken.None);

        engine.TryGetValue(One, PlcAddress.Parse("VB0"), out var recovered).Should().BeTrue();
        recovered.Quality.Should().Be(ValueQuality.Good);
        engine.GetStationStatus(One).State.Should().Be(StationState.Online);
    }

    [Fact]
    public async Task RunCycle_OfflineStation_CostsOneExchangePerCycle()
    {
        // Several frames for station 1 (41 items, at most 20 per frame; 29-byte gaps are not bridged), 1 for station 2.
        var engine = Engine([.. Enumerable.Range(0, 41).Select(i => Item(One, $"VB{i * 30}")), Item(Two, "VB0")]);
        _link.Fail(One, new PlcCommunicationException(PlcErrorKind.NoAnswer, One, "no answer"));

        var result = await engine.RunCycleAsync(CancellationToken.None);

        engine.Plan.Frames.Count(f => f.Station == One).Should().BeGreaterThan(1);
        engine.Plan.Frames.Count(f => f.Station == Two).Should().Be(1);
        _link.ExchangesWith(One).Should().Be(1);
        _link.ExchangesWith(Two).Should().Be(2, "its one frame is defined as a list, then read with READ CHANGES");
        result.Should().Match<PollResult>(r => r.FramesSent == 2 && r.FramesFailed == 1);
        engine.TryGetValue(One, PlcAddress.Parse("VB1200"), out var skipped).Should().BeTrue();
        skipped.Error.Should().Be("NoAnswer: no answer");
    }

    [Fact]
    public async Task RunCycle_CorruptReply_StationStaysOnlineAndOtherFramesAreRead()
    {
        var engine = Engine(Items(One, "VB0"));
        await engine.RunCycleAsync(CancellationToken.None);
        _link.Fail(One, new PlcCommunicationException(PlcErrorKind.FrameCorrupt, One, "bad block check"));

        await engine.RunCycleAsync(CancellationToken.None);

        engine.GetStationStatus(One).Should().Match<StationStatus>(s => s.State == StationState.Online && s.LastError == "FrameCorrupt: bad block check");
    }

    [Fact]
    public async Task RunCycle_ValueSplitAcrossTwoFrames_AssembledFromBothReplies()
    {
        _link.Set(One, ProtocolArea.V, 120, 0xDE, 0xAD, 0xBE, 0xEF);
        var engine = Engine(Items(One, [.. Enumerable.Range(0, 50).Select(i => $"VD{i * 4}")]));

        await engine.RunCycleAsync(CancellationToken.None);

        engine.TryGetValue(One, PlcAddress.Parse("VD120"), out var value).Should().BeTrue();
        Hex(value).Should().Be("DEADBEEF");
    }

    [Fact]
    public async Task RunCycle_ListenerThrows_ErrorLoggedAndPollingGoesOn()
    {
        var engine = new PollingEngine(_link, PollPlanner.Build(Items(One, "VB0")), _clock, _log.CreateLogger(), onChanges: _ => throw new InvalidOperationException("view model bug"));

        var first = await engine.RunCycleAsync(CancellationToken.None);
        var second = await engine.RunCycleAsync(CancellationToken.None);

        (first.FramesFailed, second.FramesFailed).Should().Be((0, 0));
        engine.TryGetValue(One, PlcAddress.Parse("VB0"), out var value).Should().BeTrue();
        value.Quality.Should().Be(ValueQuality.Good);
        _log.Events.Should().Contain(e => e.Level == LogEventLevel.Error && e.Exception!.Message == "view model bug");
    }

    [Fact]
    public async Task RunCycle_NothingChanged_ListenerHearsAnEmptyBatch()
    {
        var heard = new List<IReadOnlyList<ValueChange>>();
        var engine = new PollingEngine(_link, PollPlanner.Build(Items(One, "VB0")), _clock, onChanges: heard.Add);

        await engine.RunCycleAsync(CancellationToken.None);
        await engine.RunCycleAsync(CancellationToken.None);

        heard.Select(b => b.Count).Should().Equal([1, 0], "every cycle ends with its batch, so the status bar hears of it");
    }

    /// <summary>An engine whose batches with changes land in <see cref="_batches"/> (each cycle also ends with an empty one when nothing changed).</summary>
    private PollingEngine Engine(IEnumerable<WatchedItem> items) =>
        new(_link, PollPlanner.Build(items), _clock, _log.CreateLogger(), onChanges: b =>
        {
            if (b.Count > 0)
            {
                _batches.Add(b);
            }
        });

    private static string Hex(PolledValue value) => Convert.ToHexString(value.Raw.AsSpan());
}
