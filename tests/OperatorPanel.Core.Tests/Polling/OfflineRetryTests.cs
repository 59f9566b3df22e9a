using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using Serilog.Events;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>A silent station on a bus where another answers is tried once per OfflineRetryInterval, not every cycle.</summary>
public sealed class OfflineRetryTests
{
    private static readonly TimeSpan Interval = TimeSpan.FromSeconds(5);
    private readonly PollingTestClock _clock = new();
    private readonly PollingLogSink _log = new();
    private readonly FakePlcLink _link;
    private readonly PollingEngine _engine;

    public OfflineRetryTests()
    {
        _link = new FakePlcLink(_clock);
        _link.Set(Two, ProtocolArea.V, 0, 0x21);
        _engine = new PollingEngine(
            _link, PollPlanner.Build([Item(One, "VB0"), Item(Two, "VB0")]), _clock, _log.CreateLogger(), new PollingOptions { UseReadLists = false, OfflineRetryInterval = Interval });
    }

    [Fact]
    public async Task Cycle_SilentStationWhileAnotherAnswers_IsTriedOncePerIntervalAndTheOtherEveryCycle()
    {
        _link.Fail(One, NoAnswer(One));

        await _engine.RunCycleAsync(CancellationToken.None);
        for (var i = 0; i < 4; i++)
        {
            _clock.Advance(TimeSpan.FromSeconds(1));
            await _engine.RunCycleAsync(CancellationToken.None);
        }

        _link.ExchangesWith(One).Should().Be(1, "four cycles within 5 s of its failure leave it resting");
        _link.ExchangesWith(Two).Should().Be(5);
        _engine.TryGetValue(One, PlcAddress.Parse("VB0"), out var resting).Should().BeTrue();
        resting.Should().Match<PolledValue>(v => v.Quality == ValueQuality.Bad && v.Error == "NoAnswer: station 1 is silent");
        _engine.GetStationStatus(One).Should().Match<StationStatus>(s =>
            s.State == StationState.Offline && s.ConsecutiveFailures == 1 && s.NextTryAt == PollingTestClock.Start + Interval);
        _engine.GetStationStatus(Two).NextTryAt.Should().BeNull();

        _clock.Advance(TimeSpan.FromSeconds(1));
        await _engine.RunCycleAsync(CancellationToken.None);

        _link.ExchangesWith(One).Should().Be(2, "5 s after its failure it is tried again");
        _engine.GetStationStatus(One).ConsecutiveFailures.Should().Be(2);
    }

    [Fact]
    public async Task Cycle_RestingStationAnswersAtItsNextTry_IsOnlineAndPolledEveryCycle()
    {
        _link.Set(One, ProtocolArea.V, 0, 0x11);
        await _engine.RunCycleAsync(CancellationToken.None);
        _link.Fail(One, NoAnswer(One));
        await _engine.RunCycleAsync(CancellationToken.None);
        _link.Fail(One, null);
        _link.Set(One, ProtocolArea.V, 0, 0x12);

        await _engine.RunCycleAsync(CancellationToken.None);
        _engine.TryGetValue(One, PlcAddress.Parse("VB0"), out var stale).Should().BeTrue();
        stale.Should().Match<PolledValue>(v => v.Quality == ValueQuality.Stale && v.Raw[0] == 0x11);

        _clock.Advance(Interval);
        await _engine.RunCycleAsync(CancellationToken.None);
        await _engine.RunCycleAsync(CancellationToken.None);

        _engine.TryGetValue(One, PlcAddress.Parse("VB0"), out var back).Should().BeTrue();
        back.Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x12);
        _engine.GetStationStatus(One).State.Should().Be(StationState.Online);
        _link.ExchangesWith(One).Should().Be(4, "cycles 1, 2, 4 and 5: only cycle 3 was rested");
    }

    [Fact]
    public async Task Cycle_EveryStationSilent_EachIsTriedEveryCycle()
    {
        _link.Fail(One, NoAnswer(One));
        _link.Fail(Two, NoAnswer(Two));

        for (var i = 0; i < 3; i++)
        {
            await _engine.RunCycleAsync(CancellationToken.None);
        }

        _link.ExchangesWith(One).Should().Be(3, "nobody waits on a dead bus, and a returning cable should show at once");
        _link.ExchangesWith(Two).Should().Be(3);
    }

    [Fact]
    public async Task Cycle_LineBackAfterEveryStationWasSilent_EveryStationIsReadInTheFirstCycleBack()
    {
        _link.Set(One, ProtocolArea.V, 0, 0x11);
        await _engine.RunCycleAsync(CancellationToken.None);
        _link.Fail(One, new PlcCommunicationException(PlcErrorKind.PortUnavailable, One, "COM3 is gone"));
        _link.Fail(Two, new PlcCommunicationException(PlcErrorKind.PortUnavailable, Two, "COM3 is gone"));
        _clock.Advance(TimeSpan.FromSeconds(1));
        await _engine.RunCycleAsync(CancellationToken.None);
        _link.Fail(One, null);
        _link.Fail(Two, null);
        _link.Set(One, ProtocolArea.V, 0, 0x12);
        _clock.Advance(TimeSpan.FromSeconds(1));

        await _engine.RunCycleAsync(CancellationToken.None);

        _engine.TryGetValue(One, PlcAddress.Parse("VB0"), out var one).Should().BeTrue();
        one.Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x12, "silence while nobody answered is the line's, not the station's");
        _engine.TryGetValue(Two, PlcAddress.Parse("VB0"), out var two).Should().BeTrue();
        two.Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x21, "station 2 is tried after station 1 answered");
        _link.ExchangesWith(Two).Should().Be(3);
    }

    [Fact]
    public async Task Cycle_PortGoneAfterOneStationAnswered_NoStationRestsOnceNobodyAnswers()
    {
        var gone = new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, "/dev/ttyUSB0 vanished");
        _link.Set(One, ProtocolArea.V, 0, 0x11);
        await _engine.RunCycleAsync(CancellationToken.None);
        _link.Fail(Two, gone);
        await _engine.RunCycleAsync(CancellationToken.None);
        _engine.GetStationStatus(Two).NextTryAt.Should().NotBeNull("station 1 answered in the cycle the port vanished in");
        _link.Fail(One, gone);
        _clock.Advance(TimeSpan.FromSeconds(1));

        await _engine.RunCycleAsync(CancellationToken.None);

        _engine.GetStationStatus(Two).NextTryAt.Should().BeNull("nobody on the bus answers: the line is gone, not the station");
        _engine.GetStationStatus(One).NextTryAt.Should().BeNull();
        await _engine.RunCycleAsync(CancellationToken.None);
        _link.ExchangesWith(Two).Should().Be(3, "rested in the cycle nobody answered, tried in the next one");
    }

    [Fact]
    public async Task Cycle_TriggeredRefresh_TriesTheSilentStationEveryTime()
    {
        _link.Fail(One, NoAnswer(One));
        await _engine.RunCycleAsync(CancellationToken.None);
        _engine.Mode = RefreshMode.OnDemand;

        await _engine.RunCycleAsync(CancellationToken.None);
        await _engine.RunCycleAsync(CancellationToken.None);

        _link.ExchangesWith(One).Should().Be(3, "in triggered refresh someone asked for each refresh, of every station");
    }

    [Fact]
    public async Task Cycle_StationStoppedByPanel_RestsLikeASilentStation()
    {
        await _engine.RunCycleAsync(CancellationToken.None);
        _link.Fail(One, NoAnswer(One));
        _engine.NoteStoppedByPanel(One);
        await _engine.RunCycleAsync(CancellationToken.None);

        await _engine.RunCycleAsync(CancellationToken.None);

        _link.ExchangesWith(One).Should().Be(2);
        _engine.GetStationStatus(One).State.Should().Be(StationState.StoppedByPanel);
    }

    [Fact]
    public async Task Cycle_SilentStation_OneWarningWhenItFallsSilentAndOneNoteWhenItRests()
    {
        await _engine.RunCycleAsync(CancellationToken.None);
        _link.Fail(One, NoAnswer(One));

        for (var i = 0; i < 12; i++)
        {
            await _engine.RunCycleAsync(CancellationToken.None);
            _clock.Advance(TimeSpan.FromSeconds(1));
        }

        _log.Events.Where(e => e.Level == LogEventLevel.Warning).Select(e => e.RenderMessage())
            .Should().Equal("1: \"NoAnswer: station 1 is silent\" (Offline)");
        _log.Events.Where(e => e.Level == LogEventLevel.Information).Select(e => e.RenderMessage()).Should().Equal(
            "Station 1 is silent while others on the bus answer: tried every 5 s so it does not slow their refresh");
        _link.ExchangesWith(One).Should().Be(4, "cycles 1 and 2, then one try each 5 s: at 6 s and 11 s");
    }

    private static PlcCommunicationException NoAnswer(Station station) =>
        new(PlcErrorKind.NoAnswer, station, $"{station} is silent");
}
