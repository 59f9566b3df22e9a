using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Polling.Readers;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// A write over PPI (docs/ppi.md sections 5 and 7): checked for what the PPI link writes (<see cref="LinkAreas.Refusal"/>:
/// Q, M, V, SM, S and AQW, the address on the station's CPU), sent once as an S7 write-var job (a bit as a bit item, so the
/// other bits of its byte are left alone), then judged by a read job of the same bytes: confirmed, mismatch, or unknown
/// when the read-back fails. A write whose answer was lost is never sent again: the read-back settles it
/// (<see cref="LostReplyResolution"/>). The station's state follows each answer.
/// </summary>
internal sealed class PpiWriter(PollingContext context, PpiLink link) : IStationWriter
{
    public async Task<WriteResult> WriteAsync(WriteRequest request, ImmutableArray<byte> oldRaw, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(request);
        if (LinkAreas.Refusal(request.Address, LinkProtocol.Ppi, context.Plan.Cpus.GetValueOrDefault(request.Station), AddressUse.Write) is { } refusal)
        {
            return new WriteResult(new WriteOutcome.Failed(refusal, WriteFailureKind.InvalidRequest), default);
        }

        var value = request.Value.Aggregate(0u, (sum, b) => (sum << 8) | b);
        if (!PpiAddressing.TryWrite(request.Address, value, out var item, out var error))
        {
            return new WriteResult(new WriteOutcome.Failed(error, WriteFailureKind.InvalidRequest), default);
        }

        try
        {
            await link.EnsureReadyAsync(request.Station, cancellationToken).ConfigureAwait(false);
        }
        catch (PlcCommunicationException failure)
        {
            var (message, _) = context.Judge.Stations.RecordFailure(request.Station, failure);
            return new WriteResult(new WriteOutcome.Failed($"{message}; nothing was sent", WriteFailureKind.LinkFailure), default);
        }

        ImmutableArray<S7ReturnCode> codes;
        try
        {
            codes = await link.WriteAsync(request.Station, [item], cancellationToken).ConfigureAwait(false);
        }
        catch (PlcCommunicationException lost)
        {
            context.Logger.Warning("Write {Request}: {Cause}; reading the target back", request.ToString(), lost.Message);
            return await ReadBackAsync(request, (readBack, raw) => LostReplyResolution.Judge(request, oldRaw, raw, lost.Message),
                problem => LostReplyResolution.Unresolved(lost.Message, problem), cancellationToken).ConfigureAwait(false);
        }

        if (codes[0] != S7ReturnCode.Success)
        {
            var refused = $"{request.Station} refused the write of {request.Address}: {S7ReturnCodeText.Describe(codes[0])}";
            context.Judge.Stations.RecordReply(request.Station, refused);
            return new WriteResult(new WriteOutcome.Failed(refused, WriteFailureKind.RefusedByPlc), default);
        }

        context.Judge.Stations.RecordReply(request.Station);
        return await ReadBackAsync(request, (readBack, _) => readBack.AsSpan().SequenceEqual(request.Value.AsSpan())
                ? new WriteOutcome.Confirmed(readBack)
                : new WriteOutcome.ReadBackMismatch(request.Value, readBack),
            problem => new WriteOutcome.Unknown(default, $"{request.Station} accepted the write", $"the read-back failed ({problem})"), cancellationToken).ConfigureAwait(false);
    }

    /// <summary>
    /// Reads the written bytes back (the whole byte for a bit) and judges them with <paramref name="judge"/> (the value as
    /// the store holds it, the raw bytes), or the read-back's failure with <paramref name="unresolved"/>.
    /// </summary>
    private async Task<WriteResult> ReadBackAsync(
        WriteRequest request, Func<ImmutableArray<byte>, ImmutableArray<byte>, WriteOutcome> judge, Func<string, WriteOutcome> unresolved, CancellationToken cancellationToken)
    {
        var address = request.Address;
        PpiAddressing.TryRange(address.Area, address.ByteOffset, request.BitValue is null ? request.Data.Length : 1, out var item, out _);
        ImmutableArray<S7ItemResult> results;
        try
        {
            results = await link.ReadAsync(request.Station, [item], cancellationToken).ConfigureAwait(false);
        }
        catch (PlcCommunicationException failure)
        {
            var (message, _) = context.Judge.Stations.RecordFailure(request.Station, failure);
            return new WriteResult(unresolved(message), default);
        }

        if (results[0] is not { Succeeded: true } result || result.Data.Length != item.DataLength)
        {
            var problem = $"read-back of {address}: {S7ReturnCodeText.Describe(results[0].Code)}";
            context.Judge.Stations.RecordBadReply(request.Station, problem);
            return new WriteResult(unresolved(problem), default);
        }

        context.Judge.Stations.RecordReply(request.Station);
        return new WriteResult(judge(ValueStore.Extract(address, result.Data.AsSpan()), result.Data), result.Data);
    }
}
