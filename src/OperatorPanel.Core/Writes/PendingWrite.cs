namespace OperatorPanel.Core.Writes;

/// <summary>
/// A queued write and its caller's task. Cancelling the caller's token withdraws it only while it is still queued:
/// once sending has started the write runs to its outcome, so it is never half-abandoned.
/// </summary>
internal sealed class PendingWrite
{
    private const int Queued = 0;
    private const int Sending = 1;
    private const int Withdrawn = 2;

    private readonly TaskCompletionSource<WriteOutcome> _completion = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private readonly CancellationTokenRegistration _registration;
    private int _state;

    public PendingWrite(WriteRequest request, CancellationToken cancellationToken)
    {
        Request = request;
        _registration = cancellationToken.Register(() =>
        {
            if (Interlocked.CompareExchange(ref _state, Withdrawn, Queued) == Queued)
            {
                _completion.TrySetCanceled(cancellationToken);
            }
        });
    }

    public WriteRequest Request { get; }

    public Task<WriteOutcome> Task => _completion.Task;

    /// <summary>The write's intent once it is on record (Audit); its outcome is recorded under the same id.</summary>
    public Audit.AuditEntry? Intent { get; set; }

    /// <summary>False when the caller withdrew the write before it reached the wire.</summary>
    public bool TryStartSending() => Interlocked.CompareExchange(ref _state, Sending, Queued) == Queued;

    public void Complete(WriteOutcome outcome)
    {
        _registration.Dispose();
        _completion.TrySetResult(outcome);
    }
}
