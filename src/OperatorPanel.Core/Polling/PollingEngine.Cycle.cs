using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Polling;

/// <summary>One poll cycle: every frame of the plan, station by station, then the quality rules and one published batch.</summary>
public sealed partial class PollingEngine
{
    private long _cycleCount;

    /// <summary>Runs one full cycle now. Used by the loop; tests call it directly (never alongside <see cref="RunAsync"/>).</summary>
    internal async Task<PollResult> RunCycleAsync(CancellationToken cancellationToken)
    {
        var started = _time.GetUtcNow();
        List<TaskCompletionSource<PollResult>> waiters;
        lock (_gate)
        {
            waiters = [.. _refreshWaiters];
            _refreshWaiters.Clear();
            _lastCycleStart = started;
        }

        PollResult? result = null;
        try
        {
            result = await PollAllAsync(++_cycleCount, started, cancellationToken).ConfigureAwait(false);
            lock (_gate) { _lastResult = result; }
            waiters.ForEach(w => w.TrySetResult(result));
            return result;
        }
        finally
        {
            if (result is null)
            {
                waiters.ForEach(w => w.TrySetCanceled(cancellationToken));
            }
        }
    }

    private async Task<PollResult> PollAllAsync(long cycle, DateTimeOffset started, CancellationToken cancellationToken)
    {
        var reads = new FrameRead[_plan.Frames.Length];
        int sent = 0, failed = 0, writes = 0;
        var changes = new List<ValueChange>();
        var tried = new List<Station>();
        foreach (var station in _plan.Stations)
        {
            string? offlineError = null;
            writes += await ExecutePendingWritesAsync(cancellationToken).ConfigureAwait(false);
            if (IsResting(station, started) is { } restingError)
            {
                MarkFramesOffline(station, reads, restingError);
                changes.AddRange(ApplyReads(station, reads));
                continue;
            }

            tried.Add(station);
            var servedByChangesOfLists = await ReadChangesOfListsAsync(station, reads, cancellationToken).ConfigureAwait(false);
            sent += servedByChangesOfLists.Count;
            for (var i = 0; i < _plan.Frames.Length; i++)
            {
                if (_plan.Frames[i].Station != station || servedByChangesOfLists.Contains(i))
                {
                    continue;
                }

                writes += await ExecutePendingWritesAsync(cancellationToken).ConfigureAwait(false);
                if (offlineError is not null)
                {
                    reads[i] = FrameRead.Failure(offlineError, stationOffline: true);
                    continue;
                }

                sent++;
                reads[i] = await ReadFrameAsync(i, cancellationToken).ConfigureAwait(false);
                failed += reads[i].Succeeded ? 0 : 1;
                offlineError = reads[i].StationOffline ? reads[i].Error : null;
            }

            changes.AddRange(ApplyReads(station, reads));
        }

        NoteSilences(tried);
        Publish(changes);
        return new PollResult(cycle, started, _time.GetUtcNow(), sent, failed, writes, changes.Count);
    }

    private async Task<FrameRead> ReadFrameAsync(int index, CancellationToken cancellationToken)
    {
        var frame = _plan.Frames[index];
        LinkReply exchange;
        try
        {
            exchange = await ExchangeFrameAsync(index, cancellationToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            throw;
        }
        catch (Exception exception)
        {
            // A bug of ours or a broken fake, never a link failure (those are values): the loop goes on.
            var (message, offline) = _stations.RecordFailure(frame.Station, exception);
            return FrameRead.Failure(message, offline);
        }

        if (exchange.Failure is { } failure)
        {
            var (message, offline) = _stations.RecordFailure(frame.Station, failure);
            return FrameRead.Failure(message, offline);
        }

        var response = exchange.Response;
        switch (response)
        {
            case ReadResponse read when read.Data.Length == frame.DataBytes:
                _stations.RecordReply(frame.Station);
                return FrameRead.Success(read.Data);
            case ReadListResponse list when list.Data.Length == frame.DataBytes:
                _stations.RecordReply(frame.Station);
                return FrameRead.Success(list.Data);
            case ReadChangesResponse changes when ApplyChanges(index, changes) is { IsDefault: false } data:
                _stations.RecordReply(frame.Station);
                return FrameRead.Success(data);
            case ErrorResponse refused:
                var refusal = $"{frame.Station} refused READ {Describe(frame)}: {refused.Error}";
                _stations.RecordReply(frame.Station, refusal);
                return FrameRead.Refusal(refusal);
            default:
                var message = $"unexpected reply to READ {Describe(frame)}: {Describe(response)}";
                _stations.RecordBadReply(frame.Station, message);
                return FrameRead.Failure(message, stationOffline: false);
        }
    }

    /// <summary>
    /// The quality rules: all bytes read → Good; the frame was refused → Bad; the frame failed on the link → Stale
    /// when a value was read before, else Bad. A value split across frames needs all of them.
    /// </summary>
    private List<ValueChange> ApplyReads(Station station, FrameRead[] reads)
    {
        var now = _time.GetUtcNow();
        var changes = new List<ValueChange>();
        foreach (var planned in _plan.Values.Where(v => v.Item.Station == station))
        {
            var failure = planned.Slices.Select(s => reads[s.FrameIndex]).FirstOrDefault(r => !r.Succeeded);
            Func<PolledValue, PolledValue> next = failure.Error is not { } error
                ? _ => PolledValue.Good(Assemble(planned, reads), now)
                : old => failure.Refused || !old.HasValue
                    ? old with { Quality = ValueQuality.Bad, Error = error, Timestamp = now }
                    : old with { Quality = ValueQuality.Stale, Error = error };
            if (_values.Update(planned.Item, next) is { } change)
            {
                changes.Add(change);
            }
        }

        return changes;
    }

    private static ImmutableArray<byte> Assemble(PlannedValue planned, FrameRead[] reads)
    {
        var bytes = new List<byte>();
        foreach (var slice in planned.Slices)
        {
            bytes.AddRange(reads[slice.FrameIndex].Data.AsSpan(slice.DataOffset, slice.Length));
        }

        return ValueStore.Extract(planned.Item.Address, bytes.ToArray());
    }

    private static string Describe(PollFrame frame) =>
        string.Join(", ", frame.Items.Select(i => $"{i.Area}{i.Offset}+{i.Length}"));

    private static string Describe(PlcResponse? response) => response switch
    {
        null => "no reply object",
        ReadResponse read => $"{read.Data.Length} data bytes",
        ReadListResponse list => $"{list.Data.Length} data bytes",
        ReadChangesResponse { Full: true } changes => $"FULL with {changes.Data.Length} data bytes",
        ReadChangesResponse changes => $"{changes.Changes.Length} changed bytes that do not fit the list",
        ReadChangesOfListsResponse lists => $"entries for lists {string.Join(", ", lists.Lists.Select(e => e.List))} whose changes do not fit them",
        ErrorResponse error => $"error {(byte)error.Error:X2} {error.Error}",
        _ => $"{response.GetType().Name}",
    };
}
