using System.Collections.Concurrent;
using Serilog;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The one queue of a bus (S7NetPlus's TaskQueue idea): writes, IDENTIFY and STOP are queued by any thread and run by
/// the polling loop between two of its exchanges, one at a time, so one request is on the wire at a time by this one
/// mechanism (the bus is half-duplex and every station hears every frame). A job its caller withdraws before it starts
/// never runs; a job still queued when polling stops gets its abandoned outcome (a write: nothing written).
/// </summary>
internal sealed class BusQueue(ILogger logger)
{
    private readonly ConcurrentQueue<BusJob> _jobs = new();

    /// <summary>Set whenever work arrives: a job here, a refresh request or a mode change (CycleSchedule).</summary>
    public WakeSignal Wake { get; } = new();

    /// <summary>
    /// Queues <paramref name="run"/>; its result is the caller's. <paramref name="abandoned"/> gives the outcome when
    /// polling stops before the job ran (null: the caller's task is cancelled). Cancelling
    /// <paramref name="withdraw"/> withdraws the job only while it is still queued: once started it runs to its end.
    /// </summary>
    public Task<T> Enqueue<T>(string what, Func<CancellationToken, Task<T>> run, Func<T>? abandoned, CancellationToken withdraw)
    {
        var job = new BusJob<T>(what, run, abandoned, withdraw);
        _jobs.Enqueue(job);
        Wake.Set();
        return job.Task;
    }

    /// <summary>
    /// Runs every queued job, in order; returns how many ran. <paramref name="afterEach"/> runs after each job, before its
    /// caller hears the outcome (the engine hands on the job's changes then). Stops at cancellation (polling stops).
    /// </summary>
    public async Task<int> RunAsync(Action afterEach, CancellationToken cancellationToken)
    {
        var done = 0;
        while (_jobs.TryDequeue(out var job))
        {
            if (!job.TryStart())
            {
                logger.Information("{Job:l} withdrawn by the caller before it was sent", job.What);
                continue;
            }

            await job.RunAsync(logger, afterEach, cancellationToken).ConfigureAwait(false);
            done++;
            cancellationToken.ThrowIfCancellationRequested();
        }

        return done;
    }

    /// <summary>Polling stopped: every job still queued gets its abandoned outcome.</summary>
    public void AbandonAll()
    {
        while (_jobs.TryDequeue(out var job))
        {
            if (job.TryStart())
            {
                job.Abandon();
            }
        }
    }
}
