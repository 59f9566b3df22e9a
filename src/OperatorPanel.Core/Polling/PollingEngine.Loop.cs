namespace OperatorPanel.Core.Polling;

/// <summary>The loop: writes first, then a cycle when one is due, else wait on the clock or for work.</summary>
public sealed partial class PollingEngine
{
    private DateTimeOffset? _lastCycleStart;

    /// <summary>
    /// Polls and writes until <paramref name="cancellationToken"/> is cancelled, then returns normally. Queued writes
    /// that were never sent complete as <see cref="Writes.WriteFailureKind.EngineStopped"/>; pending refreshes are
    /// cancelled. Only one run at a time.
    /// </summary>
    public async Task RunAsync(CancellationToken cancellationToken)
    {
        if (Interlocked.Exchange(ref _running, 1) == 1)
        {
            throw new InvalidOperationException("The polling engine is already running.");
        }

        _logger.Information("Polling started: {Frames} READ frames per cycle, mode {Mode}", _plan.FrameCount, Mode);
        try
        {
            while (!cancellationToken.IsCancellationRequested)
            {
                var wake = _wake.Current;
                try
                {
                    await ExecutePendingWritesAsync(cancellationToken).ConfigureAwait(false);
                    var delay = DelayBeforeNextCycle();
                    if (delay == TimeSpan.Zero)
                    {
                        await RunCycleAsync(cancellationToken).ConfigureAwait(false);
                    }
                    else
                    {
                        await WaitAsync(wake, delay, cancellationToken).ConfigureAwait(false);
                    }
                }
                catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
                {
                    break;
                }
                catch (Exception exception)
                {
                    _logger.Error(exception, "Polling loop error; polling continues");
                }
            }
        }
        finally
        {
            FailPendingWork();
            Volatile.Write(ref _running, 0);
            _logger.Information("Polling stopped");
        }
    }

    /// <summary>Zero: run a cycle now (a refresh was requested, or the period is over). Null: nothing due until woken (triggered mode without a request).</summary>
    private TimeSpan? DelayBeforeNextCycle()
    {
        lock (_gate)
        {
            _refreshWaiters.RemoveAll(w => w.Task.IsCompleted);

            // "Refresh now" means now in either mode; in continuous mode it does not wait out the minimum period.
            if (_refreshWaiters.Count > 0)
            {
                return TimeSpan.Zero;
            }

            if (_mode == RefreshMode.OnDemand)
            {
                return null;
            }

            if (_lastCycleStart is not { } last)
            {
                return TimeSpan.Zero;
            }

            var remaining = last + _minimumPeriod - _time.GetUtcNow();
            return remaining > TimeSpan.Zero ? remaining : TimeSpan.Zero;
        }
    }

    private async Task WaitAsync(Task wake, TimeSpan? delay, CancellationToken cancellationToken)
    {
        if (delay is not { } due)
        {
            await wake.WaitAsync(cancellationToken).ConfigureAwait(false);
            return;
        }

        using var stopTimer = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        var timer = Task.Delay(due, _time, stopTimer.Token);
        await Task.WhenAny(wake, timer).ConfigureAwait(false);
        await stopTimer.CancelAsync().ConfigureAwait(false);
        cancellationToken.ThrowIfCancellationRequested();
    }

    private void FailPendingWork()
    {
        while (_writes.TryDequeue(out var pending))
        {
            if (pending.TryStartSending())
            {
                Finish(pending, OldValueText(pending.Request), new Writes.WriteOutcome.Failed(
                    "polling stopped before the write was sent; nothing was written", Writes.WriteFailureKind.EngineStopped));
            }
        }

        lock (_gate)
        {
            _refreshWaiters.ForEach(w => w.TrySetCanceled());
            _refreshWaiters.Clear();
        }
    }
}
