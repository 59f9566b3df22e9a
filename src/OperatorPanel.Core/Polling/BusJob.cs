using Serilog;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// One job of a <see cref="BusQueue"/> and its caller's task. Cancelling the caller's token withdraws it only while it is
/// still queued: once started it runs to its outcome, so a write is never half-abandoned.
/// </summary>
internal abstract class BusJob
{
    private const int Queued = 0;
    private const int Started = 1;
    private const int Withdrawn = 2;

    private int _state;

    protected BusJob(string what) => What = what;

    public string What { get; }

    /// <summary>False when the caller withdrew the job before it reached the wire.</summary>
    public bool TryStart() => Interlocked.CompareExchange(ref _state, Started, Queued) == Queued;

    /// <summary>Runs the job, then <paramref name="afterEach"/>, then hands its caller the outcome.</summary>
    public abstract Task RunAsync(ILogger logger, Action afterEach, CancellationToken cancellationToken);

    /// <summary>Polling stopped before the job started.</summary>
    public abstract void Abandon();

    /// <summary>For a subclass's withdrawal: true when the job was still queued.</summary>
    protected bool TryWithdraw() => Interlocked.CompareExchange(ref _state, Withdrawn, Queued) == Queued;
}

/// <summary>A <see cref="BusJob"/> whose caller waits for a <typeparamref name="T"/>.</summary>
internal sealed class BusJob<T> : BusJob
{
    private readonly TaskCompletionSource<T> _completion = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private readonly Func<CancellationToken, Task<T>> _run;
    private readonly Func<T>? _abandoned;
    private readonly CancellationTokenRegistration _registration;

    public BusJob(string what, Func<CancellationToken, Task<T>> run, Func<T>? abandoned, CancellationToken withdraw)
        : base(what)
    {
        (_run, _abandoned) = (run, abandoned);
        _registration = withdraw.Register(() =>
        {
            if (TryWithdraw())
            {
                _completion.TrySetCanceled(withdraw);
            }
        });
    }

    public Task<T> Task => _completion.Task;

    public override async Task RunAsync(ILogger logger, Action afterEach, CancellationToken cancellationToken)
    {
        _registration.Dispose();
        try
        {
            var result = await _run(cancellationToken).ConfigureAwait(false);
            afterEach();
            _completion.TrySetResult(result);
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            _completion.TrySetCanceled(cancellationToken);
            throw;
        }
        catch (Exception exception)
        {
            // A bug of ours must not leave the caller waiting forever, nor stop the bus.
            logger.Error(exception, "{Job:l} broke the bus's own handling", What);
            _completion.TrySetException(exception);
        }
    }

    public override void Abandon()
    {
        _registration.Dispose();
        if (_abandoned is null)
        {
            _completion.TrySetCanceled();
        }
        else
        {
            _completion.TrySetResult(_abandoned());
        }
    }
}
