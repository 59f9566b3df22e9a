using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// Writes: queued by any thread, sent by the loop ahead of the next READ (between two exchanges, never inside one),
/// confirmed by the read-back, logged with old and new value, never retried beyond the link's identical-frame retries.
/// </summary>
public sealed partial class PollingEngine
{
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
                Finish(pending, WriteLog.Unknown, new WriteOutcome.Failed($"internal error: {exception.Message}", WriteFailureKind.UnexpectedReply));
            }

            done++;
        }

        return done;
    }

    private async Task ExecuteWriteAsync(PendingWrite pending, CancellationToken cancellationToken)
    {
        var request = pending.Request;
        var oldValue = OldValueText(request);
        if (!WriteCommand.TryBuild(request, _plan.Cpus.GetValueOrDefault(request.Station), out var plcRequest, out var refusal))
        {
            Finish(pending, oldValue, refusal);
            return;
        }

        PlcResponse? response;
        try
        {
            response = await _link.ExchangeAsync(plcRequest, cancellationToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            Finish(pending, oldValue, new WriteOutcome.Failed(
                "polling stopped while the write was on the wire; the PLC may or may not have applied it", WriteFailureKind.EngineStopped));
            throw;
        }
        catch (Exception exception)
        {
            var (message, _) = _stations.RecordFailure(request.Station, exception);
            Finish(pending, oldValue, new WriteOutcome.Failed(message, WriteFailureKind.LinkFailure));
            return;
        }

        var outcome = WriteCommand.Interpret(request, response, out var readBack);
        if (outcome is WriteOutcome.Failed { Kind: WriteFailureKind.UnexpectedReply } odd)
        {
            _stations.RecordBadReply(request.Station, odd.Reason);
        }
        else
        {
            _stations.RecordReply(request.Station, (outcome as WriteOutcome.Failed)?.Reason);
        }

        if (!readBack.IsDefault)
        {
            var area = ProtocolAreaExtensions.FromMemoryArea(request.Address.Area)!.Value;
            Publish(_values.Apply(request.Station, area, request.Address.ByteOffset, readBack, _time.GetUtcNow()));
        }

        Finish(pending, oldValue, outcome);
    }

    private string OldValueText(WriteRequest request) =>
        _values.TryGet(new WatchedItem(request.Station, request.Address), out var old) && old.HasValue
            ? WriteLog.Format(request.Address, old.Raw)
            : WriteLog.Unknown;

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
