using System.Collections.Immutable;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling.Readers;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// A write through the generated handler (docs/protocol-v2.md, 03 WRITE and 04 WRITE BIT): built and checked for the
/// station's CPU (<see cref="WriteCommand"/>), sent once (the link never repeats a request that acts on the process),
/// confirmed by the reply's read-back or, when the reply was lost, by reading the target back
/// (<see cref="LostReplyResolution"/>: ConfirmedByReadBack, NotApplied, Unknown). The station's state follows each reply.
/// </summary>
internal sealed class FreeportWriter(PollingContext context) : IStationWriter
{
    public async Task<WriteResult> WriteAsync(WriteRequest request, ImmutableArray<byte> oldRaw, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(request);
        if (!WriteCommand.TryBuild(request, context.Plan.Cpus.GetValueOrDefault(request.Station), out var plcRequest, out var refusal))
        {
            return new WriteResult(refusal, default);
        }

        switch (await context.Link.ExchangeAsync(plcRequest, cancellationToken).ConfigureAwait(false))
        {
            case LinkReply.Answered answered:
                return Judge(request, answered.Response);
            case LinkReply.Failed { Sent: false } notSent:
                var (message, _) = context.Judge.Stations.RecordFailure(request.Station, notSent.Failure);
                return new WriteResult(new WriteOutcome.Failed($"{message}; nothing was sent", WriteFailureKind.LinkFailure), default);
            case LinkReply.Failed lost:
                return await ResolveByReadBackAsync(request, oldRaw, lost, cancellationToken).ConfigureAwait(false);
            default:
                throw new InvalidOperationException("a link reply is answered or failed");
        }
    }

    private WriteResult Judge(WriteRequest request, PlcResponse response)
    {
        var outcome = WriteCommand.Interpret(request, response, out var readBack);
        if (outcome is WriteOutcome.Failed { Kind: WriteFailureKind.UnexpectedReply } odd)
        {
            context.Judge.Stations.RecordBadReply(request.Station, odd.Reason);
        }
        else
        {
            context.Judge.Stations.RecordReply(request.Station, (outcome as WriteOutcome.Failed)?.Reason);
        }

        return new WriteResult(outcome, readBack);
    }

    /// <summary>
    /// The write's reply was lost, so the PLC may have acted: read the target back (a READ, retried as reads are) and
    /// judge it, never repeating the write. Cancellation leaves the write unknown.
    /// </summary>
    private async Task<WriteResult> ResolveByReadBackAsync(WriteRequest request, ImmutableArray<byte> oldRaw, LinkReply.Failed lost, CancellationToken cancellationToken)
    {
        var cause = lost.CorruptedCopy
            ? $"{lost.Failure.Message}; the PLC acted on a corrupted copy of the request, so it may have written another address too: check the values near {request.Address}"
            : lost.Failure.Message;
        context.Logger.Warning("Write {Request}: {Cause}; reading the target back", request.ToString(), cause);
        var readBack = LostReplyResolution.ReadBackOf(request);
        LinkReply reply;
        try
        {
            reply = await context.Link.ExchangeAsync(readBack, cancellationToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            return new WriteResult(new WriteOutcome.Unknown(default, cause, "no read-back: the panel stopped polling"), default);
        }

        if (reply.Failure is { } failure)
        {
            var (message, _) = context.Judge.Stations.RecordFailure(request.Station, failure);
            return new WriteResult(LostReplyResolution.Unresolved(cause, message), default);
        }

        if (reply.Response is not ReadResponse read || read.Data.Length != readBack.TotalLength)
        {
            var problem = reply.Response is ErrorResponse refused ? ProtocolErrorText.Describe(refused.Error) : $"a {reply.Response?.Command} reply";
            context.Judge.Stations.RecordBadReply(request.Station, $"read-back of {request.Address}: {problem}");
            return new WriteResult(LostReplyResolution.Unresolved(cause, problem), default);
        }

        context.Judge.Stations.RecordReply(request.Station);
        return new WriteResult(LostReplyResolution.Judge(request, oldRaw, read.Data, cause), read.Data);
    }
}
