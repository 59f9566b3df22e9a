using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link.V3;

/// <summary>
/// The <see cref="IPlcLink"/> face: the requests both protocols share, sent as their v3 commands, and the v3 reply
/// turned into the response type the writer, STOP (Stop/RemoteStop) and the settling of cut-short writes already judge.
/// A request v3 has no form for (a READ of several ranges or more than MAX_DATA bytes, v2's lists) fails before
/// anything is sent. An IDENTIFY reply that is not v3's says to regenerate the PLC code.
/// </summary>
public sealed partial class V3Link
{
    public async Task<LinkReply> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(request);
        if (ToV3(request) is not { } v3)
        {
            var failure = new PlcCommunicationException(PlcErrorKind.NegativeReply, request.Station,
                $"{request.Station}: {request.Command} has no protocol v3 form on {PortName} (v3 reads one range of 1-{HandlerShape.MaxData} bytes; its lists are DEFINE LIST / READ LIST)");
            return new LinkReply.Failed(failure, Sent: false);
        }

        var exchange = await ExchangeV3Async(v3, cancellationToken).ConfigureAwait(false);
        if (exchange.Reply is not { } reply)
        {
            return new LinkReply.Failed(exchange.Failure!, exchange.Sent, exchange.CorruptedCopy);
        }

        if (reply.Status.IsError())
        {
            return new LinkReply.Answered(new ErrorResponse(request.Station, 0, request.Command, (ProtocolError)((byte)reply.Status & 0x7F)) { RequestCheck = reply.RequestCheck });
        }

        if (FromV3(request, reply) is { } response)
        {
            return new LinkReply.Answered(response with { RequestCheck = reply.RequestCheck });
        }

        var kind = request is IdentifyRequest ? PlcErrorKind.HandlerOutdated : PlcErrorKind.FrameCorrupt;
        var message = request is IdentifyRequest
            ? HandlerBeforeV3.Message(request.Station, $"a handler whose IDENTIFY reply is not protocol v3's ({reply.Payload.Length} bytes, version {(reply.Payload.IsEmpty ? 0 : reply.Payload[0])})")
            : $"{request.Station}: the v3 reply to {request.Command} has status {reply.Status} and {reply.Payload.Length} payload bytes, which do not fit the request";
        return new LinkReply.Failed(new PlcCommunicationException(kind, request.Station, message), Sent: true);
    }

    private static Request? ToV3(PlcRequest request) => request switch
    {
        IdentifyRequest => Request.Identify(request.Station, 0),
        ReadRequest { Items: [var item] } when item.Length is > 0 and <= HandlerShape.MaxData => Request.Read(request.Station, 0, item),
        WriteBlockRequest w when w.Data.Length is > 0 and <= HandlerShape.MaxData => Request.Write(request.Station, 0, w.Area, w.Offset, w.Data.AsSpan()),
        WriteBitRequest b => Request.WriteBit(request.Station, 0, b.Area, b.Offset, b.Bit, b.Value),
        StopRequest => Request.Stop(request.Station, 0),
        _ => null,
    };

    /// <summary>The response for a reply with STATUS OK; null when its payload does not fit the request.</summary>
    private PlcResponse? FromV3(PlcRequest request, Reply reply)
    {
        if (reply.Status != ReplyStatus.Ok)
        {
            return null;
        }

        var p = reply.Payload;
        switch (request)
        {
            case IdentifyRequest when Identity.TryRead(p.AsSpan(), out var identity):
                _identities[request.Station] = identity;
                NoteEndTimeout(identity.EndTimeoutMs);
                NoteScan(identity.MaxScanMs);
                return AsIdentifyResponse(request.Station, identity);
            case ReadRequest read when p.Length == read.TotalLength:
                return new ReadResponse(request.Station, 0, p);
            case WriteBlockRequest write when p.Length == write.Data.Length:
                return new WriteBlockResponse(request.Station, 0, p);
            case WriteBitRequest when p.Length == 1:
                return new WriteBitResponse(request.Station, 0, p[0]);
            case StopRequest when p.IsEmpty:
                return new StopResponse(request.Station, 0);
            default:
                return null;
        }
    }

    /// <summary>Keeps the longest END_TIMEOUT_MS reported on this link, for the gap and the reply time-out.</summary>
    private void NoteEndTimeout(int endTimeoutMs)
    {
        lock (_endTimeoutLock)
        {
            _longestEndTimeoutMs = Math.Max(_longestEndTimeoutMs, endTimeoutMs);
        }
    }

    /// <summary>
    /// Keeps the longest scan an IDENTIFY on this link reported (SMW26, the longest since RUN): the reply time-out allows
    /// each of the handler's scans that long, with a quarter more, when that is more than the options' allowance.
    /// </summary>
    private void NoteScan(int maxScanMs)
    {
        lock (_endTimeoutLock)
        {
            _longestScanMs = Math.Max(_longestScanMs, maxScanMs);
        }
    }

    /// <summary>
    /// IDENTIFY v3 in the shape the bus keeps: version 3, MAX_DATA as the read limit, END_TIMEOUT_MS as the reply delay,
    /// FEATURES as they are (bit 0 STOP; bit 1 is v3's list, which the v2 readers never see: the v3 readers take the
    /// shape from <see cref="IdentityOf"/>), LIST_BYTES where v2 had its copy bytes.
    /// </summary>
    public static IdentifyResponse AsIdentifyResponse(Station station, Identity i) => new(
        station, 0, Identity.ProtocolVersion, i.HandlerRevision, i.CpuModelCode, i.CpuRevisionCode, i.WriteMask, i.MaxData,
        i.EndTimeoutMs, i.Smb6, i.StatusFlags, i.LastScanMs, i.MinScanMs, i.MaxScanMs, i.Port, i.VFirst, i.VBytes, i.Features, i.ListBytes)
    {
        V3Identity = i,
    };
}
