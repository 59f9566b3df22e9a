using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>The running loop under the manual clock: continuous and triggered modes (seed 000 §7), switching, stopping.</summary>
public sealed class PollingEngineLoopTests : IAsyncDisposable
{
    private static readonly TimeSpan Ms = TimeSpan.FromMilliseconds(1);

    private readonly PollingTestClock _clock = new();
    private readonly FakePlcLink _link;
    private readonly PollingEngine _engine;
    private readonly CancellationTokenSource _stop = new();
    private Task? _run;

    public PollingEngineLoopTests()
    {
        _link = new FakePlcLink(_clock) { ExchangeDuration = 30 * Ms };
        _engine = new PollingEngine(_link, PollPlanner.Build(Items(One, "VB0")), _clock, options: new PollingOptions { UseReadLists = false }) { MinimumPeriod = 100 * Ms };
    }

    [Fact]
    public async Task Run_Continuous_NextCycleStartsMinimumPeriodAfterThePreviousStart()
    {
        Start();
        await _clock.WhenTimerScheduledAsync().Guarded();
        _clock.Advance(69 * Ms); // the 30 ms exchange plus 69 ms: 1 ms short of the period

        _link.RequestTimes.Should().Equal(PollingTestClock.Start);

        _clock.Advance(1 * Ms);
        await _clock.WhenTimerScheduledAsync().Guarded();
        _clock.Advance(70 * Ms);
        await _clock.WhenTimerScheduledAsync().Guarded();

        _link.RequestTimes.Should().Equal(PollingTestClock.Start, PollingTestClock.Start.AddMilliseconds(100), PollingTestClock.Start.AddMilliseconds(200));
    }

    [Fact]
    public async Task RequestRefresh_ContinuousMidPeriod_CycleRunsAtOnceWithoutWaitingOutThePeriod()
    {
        Start();
        await _clock.WhenTimerScheduledAsync().Guarded();

        var result = await _engine.RequestRefreshAsync().Guarded();

        result.Cycle.Should().Be(2);
        _link.RequestTimes.Should().Equal(PollingTestClock.Start, PollingTestClock.Start.AddMilliseconds(30));
    }

    [Fact]
    public async Task NextCycle_ContinuousMidPeriod_CompletesWithTheNextRegularCycleAndAsksForNone()
    {
        Start();
        await _clock.WhenTimerScheduledAsync().Guarded();

        var next = _engine.NextCycleAsync();
        await _clock.WhenTimerScheduledAsync().Guarded();

        next.IsCompleted.Should().BeFalse("the minimum period holds: a live view following the polling must not speed it up");
        _link.RequestTimes.Should().Equal(PollingTestClock.Start);
        _clock.Advance(70 * Ms);
        var result = await next.Guarded();
        result.Cycle.Should().Be(2);
        _link.RequestTimes.Should().Equal(PollingTestClock.Start, PollingTestClock.Start.AddMilliseconds(100));
    }

    [Fact]
    public async Task NextCycle_OnDemand_AsksForTheCycle()
    {
        _engine.Mode = RefreshMode.OnDemand;
        Start();

        var result = await _engine.NextCycleAsync().Guarded();

        result.Cycle.Should().Be(1, "in triggered mode no cycle comes unasked");
        _link.RequestTimes.Should().ContainSingle();
    }

    [Fact]
    public async Task Run_CycleLongerThanMinimumPeriod_NextCycleStartsAtOnce()
    {
        _engine.MinimumPeriod = 20 * Ms;
        _link.OnExchange = _ =>
        {
            if (_link.Requests.Count == 3)
            {
                _link.ExchangeDuration = TimeSpan.Zero; // let the loop come to rest on the timer
            }
        };

        Start();
        await _clock.WhenTimerScheduledAsync().Guarded();

        _link.RequestTimes.Should().Equal(PollingTestClock.Start, PollingTestClock.Start.AddMilliseconds(30), PollingTestClock.Start.AddMilliseconds(60));
    }

    [Fact]
    public async Task Run_OnDemand_PollsNothingUntilRefreshThenExactlyOneCycle()
    {
        _engine.Mode = RefreshMode.OnDemand;
        Start();
        var write = await _engine.WriteAsync(WriteRequest.Bytes(One, PlcAddress.Parse("VB9"), [0x01])).Guarded();
        _clock.Advance(TimeSpan.FromMinutes(5));

        write.Should().BeOfType<WriteOutcome.Confirmed>();
        _link.Requests.Should().ContainSingle().Which.Should().BeOfType<WriteBlockRequest>();

        var result = await _engine.RequestRefreshAsync().Guarded();
        _clock.Advance(TimeSpan.FromMinutes(5));
        await _engine.WriteAsync(WriteRequest.Bytes(One, PlcAddress.Parse("VB9"), [0x02])).Guarded();

        result.Should().Match<PollResult>(r => r.Cycle == 1 && r.FramesSent == 1);
        _link.Requests.Select(r => r.Command).Should().Equal(CommandCode.Write, CommandCode.Read, CommandCode.Write);
    }

    [Fact]
    public async Task Run_SwitchedFromOnDemandToContinuous_StartsPollingAtOnce()
    {
        _engine.Mode = RefreshMode.OnDemand;
        Start();
        await _engine.WriteAsync(WriteRequest.Bytes(One, PlcAddress.Parse("VB9"), [0x01])).Guarded();

        _engine.Mode = RefreshMode.Continuous;
        await _clock.WhenTimerScheduledAsync().Guarded();

        _link.Requests.Select(r => r.Command).Should().Equal(CommandCode.Write, CommandCode.Read);
    }

    [Fact]
    public async Task Run_SwitchedToOnDemand_StopsPolling()
    {
        Start();
        await _clock.WhenTimerScheduledAsync().Guarded();

        _engine.Mode = RefreshMode.OnDemand;
        await _engine.WriteAsync(WriteRequest.Bytes(One, PlcAddress.Parse("VB9"), [0x01])).Guarded();
        _clock.Advance(TimeSpan.FromMinutes(1));
        await _engine.WriteAsync(WriteRequest.Bytes(One, PlcAddress.Parse("VB9"), [0x02])).Guarded();

        _link.Requests.Select(r => r.Command).Should().Equal(CommandCode.Read, CommandCode.Write, CommandCode.Write);
    }

    [Fact]
    public async Task Run_LinkThrowsEveryTime_LoopKeepsPollingAtTheMinimumPeriod()
    {
        _link.Fail(One, new IOException("cable pulled"));
        Start();
        await _clock.WhenTimerScheduledAsync().Guarded();
        _clock.Advance(70 * Ms);
        await _clock.WhenTimerScheduledAsync().Guarded();

        _link.Requests.Should().HaveCount(2);
        _engine.GetStationStatus(One).Should().Match<StationStatus>(s => s.State == StationState.Offline && s.ConsecutiveFailures == 2);
        _run!.IsCompleted.Should().BeFalse();
    }

    [Fact]
    public async Task Run_Stopped_QueuedWriteFailsAsEngineStoppedAndRefreshIsCancelled()
    {
        _engine.Mode = RefreshMode.OnDemand;
        var write = _engine.WriteAsync(WriteRequest.Bytes(One, PlcAddress.Parse("VB9"), [0x01]));
        using var stopped = new CancellationTokenSource();
        await stopped.CancelAsync();

        await _engine.RunAsync(stopped.Token).Guarded();
        var refresh = _engine.RequestRefreshAsync();
        await _engine.RunAsync(stopped.Token).Guarded();

        (await write.Guarded()).Should().Match<WriteOutcome>(o => o is WriteOutcome.Failed && ((WriteOutcome.Failed)o).Kind == WriteFailureKind.EngineStopped);
        refresh.IsCanceled.Should().BeTrue();
        _link.Requests.Should().BeEmpty();
    }

    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync();
        if (_run is not null)
        {
            await _run.Guarded();
        }

        _stop.Dispose();
    }

    private void Start() => _run = Task.Run(() => _engine.RunAsync(_stop.Token));
}
