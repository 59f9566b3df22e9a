using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The loop: the bus's queued jobs first (writes, IDENTIFY, STOP), then a cycle when one is due, else wait on the clock
/// or for work. A cycle goes station by station: queued jobs ahead of each exchange, the station's readers asked in order
/// for its frames not read yet, the quality rules (<see cref="CycleReads"/>), and one batch handed on at its end.
/// </summary>
internal sealed partial class PollingEngine
{
    private long _cycleCount;
    private int _running;

    /// <summary>
    /// Polls and runs the queue's jobs until <paramref name="cancellationToken"/> is cancelled, then returns normally.
    /// Queued jobs that never started get their abandoned outcome (a write: <see cref="WriteFailureKind.EngineStopped"/>);
    /// pending refreshes are cancelled. Only one run at a time.
    /// </summary>
    public async Task RunAsync(CancellationToken cancellationToken)
    {
        if (Interlocked.Exchange(ref _running, 1) == 1)
        {
            throw new InvalidOperationException("The polling engine is already running.");
        }

        _context.Logger.Information("Polling started: {Frames} READ frames per cycle, mode {Mode}", Plan.FrameCount, Mode);
        try
        {
            while (!cancellationToken.IsCancellationRequested)
            {
                var wake = _queue.Wake.Current;
                try
                {
                    await _queue.RunAsync(Flush, cancellationToken).ConfigureAwait(false);
                    var delay = _schedule.DelayBeforeNextCycle();
                    if (delay == TimeSpan.Zero)
                    {
                        await RunCycleAsync(cancellationToken).ConfigureAwait(false);
                    }
                    else
                    {
                        await _schedule.WaitAsync(wake, delay, cancellationToken).ConfigureAwait(false);
                    }
                }
                catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
                {
                    break;
                }
                catch (Exception exception)
                {
                    _context.Logger.Error(exception, "Polling loop error; polling continues");
                }
            }
        }
        finally
        {
            _queue.AbandonAll();
            _schedule.CancelWaiters();
            Volatile.Write(ref _running, 0);
            _context.Logger.Information("Polling stopped");
        }
    }

    /// <summary>Runs one full cycle now. Used by the loop; tests call it directly (never alongside <see cref="RunAsync"/>).</summary>
    internal async Task<PollResult> RunCycleAsync(CancellationToken cancellationToken)
    {
        var started = _context.Time.GetUtcNow();
        var waiters = _schedule.Start(started);
        try
        {
            var result = await PollAllAsync(++_cycleCount, started, cancellationToken).ConfigureAwait(false);
            waiters.ForEach(w => w.TrySetResult(result));
            return result;
        }
        catch (Exception)
        {
            waiters.ForEach(w => w.TrySetCanceled(cancellationToken));
            throw;
        }
    }

    private async Task<PollResult> PollAllAsync(long cycle, DateTimeOffset started, CancellationToken cancellationToken)
    {
        var reads = new CycleReads(Plan);
        var changes = new List<ValueChange>();
        var tried = new List<Station>();
        var jobs = 0;
        foreach (var station in Plan.Stations)
        {
            jobs += await _queue.RunAsync(Flush, cancellationToken).ConfigureAwait(false);
            var frames = Enumerable.Range(0, Plan.Frames.Length).Where(i => Plan.Frames[i].Station == station).ToList();
            if (_rest.IsResting(station, started, Mode, Options.OfflineRetryInterval) is { } restingError)
            {
                reads.MarkOffline(frames, restingError);
            }
            else
            {
                tried.Add(station);
                jobs += await ReadStationAsync(station, frames, reads, cancellationToken).ConfigureAwait(false);
            }

            changes.AddRange(reads.Apply(station, _values, _context.Time.GetUtcNow()));
        }

        _rest.NoteSilences(Plan.Stations, tried, Options.OfflineRetryInterval);
        _batch.AddRange(changes);
        Flush();
        return new PollResult(cycle, started, _context.Time.GetUtcNow(), reads.Sent, reads.Failed, jobs, changes.Count);
    }

    /// <summary>
    /// Reads the station's frames, one exchange at a time with the queue's jobs between, until each is read or the station
    /// went silent (then the rest wait for the next cycle: at most one time-out per station and cycle). Returns the jobs run.
    /// </summary>
    private async Task<int> ReadStationAsync(Station station, List<int> pending, CycleReads reads, CancellationToken cancellationToken)
    {
        var jobs = 0;
        while (pending.Count > 0)
        {
            jobs += await _queue.RunAsync(Flush, cancellationToken).ConfigureAwait(false);
            foreach (var (frame, read) in await ReadNextAsync(station, pending, cancellationToken).ConfigureAwait(false))
            {
                reads.Record(frame, read);
                pending.Remove(frame);
                if (read.StationOffline)
                {
                    reads.MarkOffline(pending, read.Error!);
                    return jobs;
                }
            }
        }

        return jobs;
    }

    /// <summary>The first of the station's readers that takes any of the pending frames reads them.</summary>
    private async Task<IReadOnlyList<(int Frame, FrameRead Read)>> ReadNextAsync(Station station, List<int> pending, CancellationToken cancellationToken)
    {
        try
        {
            foreach (var reader in _readers.ReadersOf(station))
            {
                if (await reader.ReadAsync(pending, cancellationToken).ConfigureAwait(false) is { Count: > 0 } read)
                {
                    return read;
                }
            }

            throw new InvalidOperationException($"no reader of {station} took frame {pending[0]}");
        }
        catch (Exception exception) when (exception is not OperationCanceledException || !cancellationToken.IsCancellationRequested)
        {
            // A bug of ours or of a link, never a link failure (those are values): the frame fails, polling goes on.
            return [(pending[0], _context.Judge.Failed(station, exception))];
        }
    }
}
