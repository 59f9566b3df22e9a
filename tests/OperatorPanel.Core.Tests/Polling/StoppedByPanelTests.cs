using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using Serilog.Events;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>A station the panel stopped: shown as such, its silence not logged as news, back online when it answers.</summary>
public sealed class StoppedByPanelTests
{
    private readonly PollingTestClock _clock = new();
    private readonly PollingLogSink _log = new();
    private readonly FakePlcLink _link;
    private readonly PollingEngine _engine;

    public StoppedByPanelTests()
    {
        _link = new FakePlcLink(_clock);
        _engine = new PollingEngine(_link, PollPlanner.Build(Items(One, "VB0", "QB0")), _clock, _log.CreateLogger(), new PollingOptions { UseReadLists = false });
    }

    [Fact]
    public async Task Cycle_StoppedStationSilent_StaysStoppedByPanelAndLogsNoWarning()
    {
        await _engine.RunCycleAsync(CancellationToken.None);
        _link.Fail(One, new PlcCommunicationException(PlcErrorKind.NoAnswer, One, "no answer"));
        _engine.NoteStoppedByPanel(One);
        var warningsBefore = Warnings();

        await _engine.RunCycleAsync(CancellationToken.None);
        await _engine.RunCycleAsync(CancellationToken.None);

        _engine.GetStationStatus(One).Should().Match<StationStatus>(s =>
            s.State == StationState.StoppedByPanel && s.LastError == "stopped by the panel" && s.ConsecutiveFailures == 2);
        Warnings().Should().Be(warningsBefore, "a station the panel stopped is expected to be silent");
        _link.ExchangesWith(One).Should().Be(3, "one exchange per cycle: the first silence skips the station's other frames");
    }

    [Fact]
    public async Task Cycle_StoppedStationAnswersAgain_IsOnline()
    {
        _engine.NoteStoppedByPanel(One);

        await _engine.RunCycleAsync(CancellationToken.None);

        _engine.GetStationStatus(One).State.Should().Be(StationState.Online);
        _log.Events.Should().Contain(e => e.RenderMessage() == "Station 1 answers again after the panel stopped it: someone set RUN");
    }

    [Fact]
    public async Task Cycle_StoppedStationLosesItsPort_IsOfflineWithAWarning()
    {
        _engine.NoteStoppedByPanel(One);
        _link.Fail(One, new PlcCommunicationException(PlcErrorKind.PortUnavailable, One, "COM9 is gone"));

        await _engine.RunCycleAsync(CancellationToken.None);

        _engine.GetStationStatus(One).Should().Match<StationStatus>(s => s.State == StationState.Offline && s.LastError == "PortUnavailable: COM9 is gone");
        Warnings().Should().Be(1);
    }

    private int Warnings() => _log.Events.Count(e => e.Level == LogEventLevel.Warning);
}
