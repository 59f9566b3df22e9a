using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Transport;

/// <summary>The TestKit clock the transport tests rely on: Delay and timed cancellation complete on Advance only.</summary>
public sealed class ManualTimeProviderTests
{
    private readonly ManualTimeProvider _clock = new();

    [Fact]
    public async Task Delay_ClockAdvancedPastDueTime_Completes()
    {
        var delay = Task.Delay(TimeSpan.FromSeconds(10), _clock);

        _clock.Advance(TimeSpan.FromSeconds(9));
        delay.IsCompleted.Should().BeFalse();
        _clock.Advance(TimeSpan.FromSeconds(1));

        await delay;
        delay.IsCompletedSuccessfully.Should().BeTrue();
    }

    [Fact]
    public void CancellationTokenSource_WithManualClock_CancelsOnAdvance()
    {
        using var cancel = new CancellationTokenSource(TimeSpan.FromMilliseconds(500), _clock);

        _clock.Advance(TimeSpan.FromMilliseconds(499));
        cancel.IsCancellationRequested.Should().BeFalse();
        _clock.Advance(TimeSpan.FromMilliseconds(1));

        cancel.IsCancellationRequested.Should().BeTrue();
    }

    [Fact]
    public void PeriodicTimer_AdvancedThreePeriods_FiresThreeTimesAtItsDueTimes()
    {
        var start = _clock.GetUtcNow();
        var fired = new List<TimeSpan>();
        using var timer = _clock.CreateTimer(_ => fired.Add(_clock.GetUtcNow() - start), null, TimeSpan.FromSeconds(1), TimeSpan.FromSeconds(1));

        _clock.Advance(TimeSpan.FromSeconds(3.5));

        fired.Should().Equal(TimeSpan.FromSeconds(1), TimeSpan.FromSeconds(2), TimeSpan.FromSeconds(3));
        (_clock.GetUtcNow() - start).Should().Be(TimeSpan.FromSeconds(3.5));
    }

    [Fact]
    public void DisposedTimer_DoesNotFire()
    {
        var fired = 0;
        var timer = _clock.CreateTimer(_ => fired++, null, TimeSpan.FromSeconds(1), System.Threading.Timeout.InfiniteTimeSpan);

        timer.Dispose();
        _clock.Advance(TimeSpan.FromSeconds(2));

        fired.Should().Be(0);
    }

    [Fact]
    public void GetElapsedTime_FollowsAdvance()
    {
        var before = _clock.GetTimestamp();

        _clock.Advance(TimeSpan.FromMilliseconds(250));

        _clock.GetElapsedTime(before).Should().Be(TimeSpan.FromMilliseconds(250));
    }
}
