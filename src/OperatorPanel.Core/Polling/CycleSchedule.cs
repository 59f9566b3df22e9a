namespace OperatorPanel.Core.Polling;

/// <summary>
/// When the next poll cycle is due (seed 000 §7, the two refresh modes): continuous, at most one cycle per minimum period
/// from the previous cycle's start, or on demand, only when someone asks for a refresh; a refresh request means now in
/// either mode. Thread-safe: the mode and refresh requests come from any thread, and wake the polling loop.
/// </summary>
internal sealed class CycleSchedule(WakeSignal wake, TimeProvider time)
{
    private readonly Lock _gate = new();
    private readonly List<TaskCompletionSource<PollResult>> _waiters = [];

    // Waiting for the next cycle without making it due (a live view following continuous polling).
    private readonly List<TaskCompletionSource<PollResult>> _followers = [];
    private RefreshMode _mode = RefreshMode.Continuous;
    private TimeSpan _minimumPeriod = TimeSpan.FromMilliseconds(100);
    private DateTimeOffset? _lastStart;

    public RefreshMode Mode
    {
        get { lock (_gate) { return _mode; } }
        set { lock (_gate) { _mode = value; } wake.Set(); }
    }

    public TimeSpan MinimumPeriod
    {
        get { lock (_gate) { return _minimumPeriod; } }
        set
        {
            ArgumentOutOfRangeException.ThrowIfLessThan(value, TimeSpan.Zero);
            lock (_gate) { _minimumPeriod = value; }
            wake.Set();
        }
    }

    /// <summary>A refresh request: completes with the cycle that serves it, cancelled when polling stops first.</summary>
    public Task<PollResult> RequestRefresh(CancellationToken cancellationToken)
    {
        var waiter = new TaskCompletionSource<PollResult>(TaskCreationOptions.RunContinuationsAsynchronously);
        cancellationToken.Register(() => waiter.TrySetCanceled(cancellationToken));
        lock (_gate) { _waiters.Add(waiter); }
        wake.Set();
        return waiter.Task;
    }

    /// <summary>
    /// The next cycle, without asking for it: in continuous mode the next regular one (the minimum period still holds),
    /// in triggered mode, where no cycle comes unasked, a refresh request. Cancelled when polling stops first.
    /// </summary>
    public Task<PollResult> NextCycle(CancellationToken cancellationToken)
    {
        var follower = new TaskCompletionSource<PollResult>(TaskCreationOptions.RunContinuationsAsynchronously);
        cancellationToken.Register(() => follower.TrySetCanceled(cancellationToken));
        lock (_gate)
        {
            (_mode == RefreshMode.OnDemand ? _waiters : _followers).Add(follower);
        }

        wake.Set();
        return follower.Task;
    }

    /// <summary>A cycle starts now: it serves every refresh request and every wait for the next cycle made so far.</summary>
    public List<TaskCompletionSource<PollResult>> Start(DateTimeOffset now)
    {
        lock (_gate)
        {
            List<TaskCompletionSource<PollResult>> waiters = [.. _waiters, .. _followers];
            _waiters.Clear();
            _followers.Clear();
            _lastStart = now;
            return waiters;
        }
    }

    /// <summary>Zero: run a cycle now (a refresh was requested, or the period is over). Null: nothing due until woken.</summary>
    public TimeSpan? DelayBeforeNextCycle()
    {
        lock (_gate)
        {
            _waiters.RemoveAll(w => w.Task.IsCompleted);
            _followers.RemoveAll(w => w.Task.IsCompleted);

            // "Refresh now" means now in either mode; in continuous mode it does not wait out the minimum period.
            if (_waiters.Count > 0)
            {
                return TimeSpan.Zero;
            }

            if (_mode == RefreshMode.OnDemand)
            {
                return null;
            }

            if (_lastStart is not { } last)
            {
                return TimeSpan.Zero;
            }

            var remaining = last + _minimumPeriod - time.GetUtcNow();
            return remaining > TimeSpan.Zero ? remaining : TimeSpan.Zero;
        }
    }

    /// <summary>Waits for <paramref name="wake"/> (new work) or, when a cycle is due later, its <paramref name="delay"/>.</summary>
    public async Task WaitAsync(Task wake, TimeSpan? delay, CancellationToken cancellationToken)
    {
        if (delay is not { } due)
        {
            await wake.WaitAsync(cancellationToken).ConfigureAwait(false);
            return;
        }

        using var stopTimer = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        var timer = Task.Delay(due, time, stopTimer.Token);
        await Task.WhenAny(wake, timer).ConfigureAwait(false);
        await stopTimer.CancelAsync().ConfigureAwait(false);
        cancellationToken.ThrowIfCancellationRequested();
    }

    /// <summary>Polling stopped: every refresh request still waiting is cancelled.</summary>
    public void CancelWaiters()
    {
        lock (_gate)
        {
            _waiters.ForEach(w => w.TrySetCanceled());
            _waiters.Clear();
            _followers.ForEach(w => w.TrySetCanceled());
            _followers.Clear();
        }
    }
}
