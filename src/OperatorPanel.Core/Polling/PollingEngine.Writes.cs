using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// The write queue: writes queued by any thread, sent by the loop ahead of the next exchange (never inside one) through
/// the bus's <see cref="IStationWriter"/>, logged with old and new value, their read-back published as values.
/// </summary>
public sealed partial class PollingEngine
{
    private async Task<int> ExecutePendingWritesAsync(CancellationToken cancellationToken)
    {
        var done = 0;
        while (_writes.TryDequeue(out var pending))
        {
            if (!pending.TryStartSending())
            {
                _context.Logger.Information("Write {Request} withdrawn by the caller before it was sent", pending.Request.ToString());
                continue;
            }

            try
            {
                await ExecuteWriteAsync(pending, cancellationToken).ConfigureAwait(false);
            }
            catch (Exception exception) when (exception is not OperationCanceledException || !cancellationToken.IsCancellationRequested)
            {
                // A bug of ours must not leave the caller waiting forever: the write still gets an outcome.
                _context.Logger.Error(exception, "Write {Request} broke the engine's own handling", pending.Request.ToString());
                Finish(pending, WriteLog.Unknown, new WriteOutcome.Unknown(
                    default, $"internal error: {exception.Message}", "the panel's own handling broke after the write may have been sent"));
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
        WriteResult result;
        try
        {
            result = await _readers.Writer.WriteAsync(request, oldRaw, cancellationToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            Finish(pending, oldValue, new WriteOutcome.Unknown(
                default, "polling stopped while the write was on the wire", "no read-back: the panel stopped polling"));
            throw;
        }

        if (!result.ReadBack.IsDefault)
        {
            var area = ProtocolAreaExtensions.FromMemoryArea(request.Address.Area)!.Value;
            Publish(_values.Apply(request.Station, area, request.Address.ByteOffset, result.ReadBack, _context.Time.GetUtcNow()));
        }

        Finish(pending, oldValue, result.Outcome);
    }

    private ImmutableArray<byte> OldValue(WriteRequest request) =>
        _values.TryGet(new WatchedItem(request.Station, request.Address), out var old) && old.HasValue ? old.Raw : default;

    private void Finish(PendingWrite pending, string oldValue, WriteOutcome outcome)
    {
        if (pending.Task.IsCompleted)
        {
            return;
        }

        WriteLog.Record(_context.Logger, pending.Request, oldValue, outcome);
        pending.Complete(outcome);
    }

    private void FailPendingWork()
    {
        while (_writes.TryDequeue(out var pending))
        {
            if (pending.TryStartSending())
            {
                Finish(pending, WriteLog.Format(pending.Request.Address, OldValue(pending.Request)), new WriteOutcome.Failed(
                    "polling stopped before the write was sent; nothing was written", WriteFailureKind.EngineStopped));
            }
        }

        _schedule.CancelWaiters();
    }
}
