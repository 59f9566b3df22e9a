using System.Collections.Immutable;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// Writes: queued by any thread, sent by the loop ahead of the next READ (between two exchanges, never inside one),
/// sent once (<see cref="IPlcLink.ExchangeOnceAsync"/>), confirmed by the reply's read-back or, when the reply was lost,
/// by reading the target back (WriteOutcome.ConfirmedByReadBack, NotApplied, Unknown), logged with old and new value.
/// With <see cref="Audit"/>, each write's intent is on record before its frame leaves and its outcome before the caller
/// hears it; a write whose intent cannot be recorded is not sent.
/// </summary>
public sealed partial class PollingEngine
{
    /// <summary>Where writes go on record (the write journal), with the bus's port and the user; null records nothing.</summary>
    public AuditContext? Audit { get; init; }

    /// <summary>
    /// Queues a write and returns its outcome once sent and read back. The write waits while <see cref="RunAsync"/> is
    /// not running. Cancelling <paramref name="cancellationToken"/> withdraws it only while it is still queued.
    /// </summary>
    public Task<WriteOutcome> WriteAsync(WriteRequest request, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        var pending = new PendingWrite(request, cancellationToken);
        _writes.Enqueue(pending);
        _wake.Set();
        return pending.Task;
    }

    private async Task<int> ExecutePendingWritesAsync(CancellationToken cancellationToken)
    {
        var done = 0;
        while (_writes.TryDequeue(out var pending))
        {
            if (!pending.TryStartSending())
            {
                _logger.Information("Write {Request} withdrawn by the caller before it was sent", pending.Request.ToString());
                continue;
            }

            try
            {
                await ExecuteWriteAsync(pending, cancellationToken).ConfigureAwait(false);
            }
            catch (Exception exception) when (exception is not OperationCanceledException || !cancellationToken.IsCancellationRequested)
            {
                // A bug of ours must not leave the caller waiting forever: the write still gets an outcome.
                _logger.Error(exception, "Write {Request} broke the engine's own handling", pending.Request.ToString());
                await FinishAsync(pending, WriteLog.Unknown, new WriteOutcome.Unknown(
                    default, $"internal error: {exception.Message}", "the panel's own handling broke after the write may have been sent")).ConfigureAwait(false);
            }

            done++;
        }

        return done;
    }

    private async Task ExecuteWriteAsync(PendingWrite pending, CancellationToken cancellationToken)
    {
        var request = pending.Request;
        var oldRaw = OldValue(request);
        var oldValue = WriteLog.Format(request.Address, oldRaw);
        if (!WriteCommand.TryBuild(request, _plan.Cpus.GetValueOrDefault(request.Station), out var plcRequest, out var refusal))
        {
            Finish(pending, oldValue, refusal);
            return;
        }

        if (await RecordIntentAsync(pending, oldValue).ConfigureAwait(false) is { } notRecorded)
        {
            Finish(pending, oldValue, notRecorded);
            return;
        }

        OnceReply reply;
        try
        {
            reply = await _link.ExchangeOnceAsync(plcRequest, cancellationToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            await FinishAsync(pending, oldValue, new WriteOutcome.Unknown(
                default, "polling stopped while the write was on the wire", "no read-back: the panel stopped polling")).ConfigureAwait(false);
            throw;
        }
        catch (Exception exception)
        {
            var (message, _) = _stations.RecordFailure(request.Station, exception);
            await FinishAsync(pending, oldValue, LostReplyResolution.Unresolved("the link failed while sending", message)).ConfigureAwait(false);
            return;
        }

        switch (reply)
        {
            case OnceReply.Answered answered:
                await FinishAsync(pending, oldValue, Judge(request, answered.Response)).ConfigureAwait(false);
                break;
            case OnceReply.NotSent notSent:
                var (message, _) = _stations.RecordFailure(request.Station, notSent.Failure);
                await FinishAsync(pending, oldValue, new WriteOutcome.Failed($"{message}; nothing was sent", WriteFailureKind.LinkFailure)).ConfigureAwait(false);
                break;
            case OnceReply.ReplyLost lost:
                await FinishAsync(pending, oldValue, await ResolveByReadBackAsync(request, oldRaw, lost, cancellationToken).ConfigureAwait(false)).ConfigureAwait(false);
                break;
            default:
                throw new InvalidOperationException($"unknown link reply {reply}");
        }
    }

    private WriteOutcome Judge(WriteRequest request, PlcResponse response)
    {
        var outcome = WriteCommand.Interpret(request, response, out var readBack);
        if (outcome is WriteOutcome.Failed { Kind: WriteFailureKind.UnexpectedReply } odd)
        {
            _stations.RecordBadReply(request.Station, odd.Reason);
        }
        else
        {
            _stations.RecordReply(request.Station, (outcome as WriteOutcome.Failed)?.Reason);
        }

        PublishReadBack(request, readBack);
        return outcome;
    }

    /// <summary>
    /// The write's reply was lost, so the PLC may have acted: read the target back (a READ, retried as reads are) and
    /// judge it, never repeating the write. Cancellation leaves the write unknown.
    /// </summary>
    private async Task<WriteOutcome> ResolveByReadBackAsync(
        WriteRequest request, ImmutableArray<byte> oldRaw, OnceReply.ReplyLost lost, CancellationToken cancellationToken)
    {
        var cause = lost.CorruptedCopy
            ? $"{lost.Cause}; the PLC acted on a corrupted copy of the request, so it may have written another address too: check the values near {request.Address}"
            : lost.Cause;
        _logger.Warning("Write {Request}: {Cause}; reading the target back", request.ToString(), cause);
        PlcResponse response;
        try
        {
            response = await _link.ExchangeAsync(LostReplyResolution.ReadBackOf(request), cancellationToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            return new WriteOutcome.Unknown(default, cause, "no read-back: the panel stopped polling");
        }
        catch (Exception exception)
        {
            var (message, _) = _stations.RecordFailure(request.Station, exception);
            return LostReplyResolution.Unresolved(cause, message);
        }

        if (response is not ReadResponse read || read.Data.Length != LostReplyResolution.ReadBackOf(request).TotalLength)
        {
            var problem = response is ErrorResponse refused ? ProtocolErrorText.Describe(refused.Error) : $"a {response?.Command} reply";
            _stations.RecordBadReply(request.Station, $"read-back of {request.Address}: {problem}");
            return LostReplyResolution.Unresolved(cause, problem);
        }

        _stations.RecordReply(request.Station);
        PublishReadBack(request, read.Data);
        return LostReplyResolution.Judge(request, oldRaw, read.Data, cause);
    }

    private void PublishReadBack(WriteRequest request, ImmutableArray<byte> readBack)
    {
        if (!readBack.IsDefault)
        {
            var area = ProtocolAreaExtensions.FromMemoryArea(request.Address.Area)!.Value;
            Publish(_values.Apply(request.Station, area, request.Address.ByteOffset, readBack, _time.GetUtcNow()));
        }
    }

    private ImmutableArray<byte> OldValue(WriteRequest request) =>
        _values.TryGet(new WatchedItem(request.Station, request.Address), out var old) && old.HasValue ? old.Raw : default;

    private string OldValueText(WriteRequest request) => WriteLog.Format(request.Address, OldValue(request));

    /// <summary>Puts the intent on record before the frame leaves; null when recorded (or no audit), else the write's refusal.</summary>
    private async Task<WriteOutcome?> RecordIntentAsync(PendingWrite pending, string oldValue)
    {
        if (Audit is not { } audit)
        {
            return null;
        }

        var intent = WriteAudit.Intent(pending.Request, oldValue, audit, _time.GetUtcNow());
        if (await audit.Trail.RecordAsync(intent, CancellationToken.None).ConfigureAwait(false) is { } notKept)
        {
            return new WriteOutcome.Failed($"the write was not sent: it could not be put on record ({notKept})", WriteFailureKind.NotRecorded);
        }

        pending.Intent = intent;
        return null;
    }

    /// <summary>Records the outcome of a write whose intent is on record (the caller hears it after), then finishes it.</summary>
    private async Task FinishAsync(PendingWrite pending, string oldValue, WriteOutcome outcome)
    {
        if (pending.Intent is { } intent && !pending.Task.IsCompleted && Audit is { } audit
            && await audit.Trail.RecordAsync(WriteAudit.Outcome(intent, pending.Request, outcome, _time.GetUtcNow()), CancellationToken.None).ConfigureAwait(false) is { } notKept)
        {
            _logger.Warning("Write {Request}: its outcome could not be put on record: {Reason:l}", pending.Request.ToString(), notKept);
        }

        Finish(pending, oldValue, outcome);
    }

    private void Finish(PendingWrite pending, string oldValue, WriteOutcome outcome)
    {
        if (pending.Task.IsCompleted)
        {
            return;
        }

        WriteLog.Record(_logger, pending.Request, oldValue, outcome);
        pending.Complete(outcome);
    }
}
