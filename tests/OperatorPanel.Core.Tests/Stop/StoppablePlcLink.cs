using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Stop;

/// <summary>
/// A hand-written <see cref="IPlcLink"/> for one station that answers IDENTIFY with its FEATURES byte and meets STOP
/// with a <see cref="StopFate"/>. Once stopped it is silent, as a CPU in STOP is on Freeport: every request fails
/// with NoAnswer. Records every request.
/// </summary>
internal sealed class StoppablePlcLink(Station station, byte features = HandlerIdentity.StopFeature) : IPlcLink
{
    public StopFate Fate { get; set; } = StopFate.Executed;

    /// <summary>The failure of every request after STOP was sent, when set: the check itself fails (port gone, garbled).</summary>
    public PlcCommunicationException? FailureAfterStop { get; set; }

    /// <summary>The CPU is in STOP: silent on Freeport. Set it to start with a stopped CPU.</summary>
    public bool InStop { get; set; }

    public List<PlcRequest> Sent { get; } = [];

    public Task<LinkReply> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        if (request is StopRequest)
        {
            return Task.FromResult(Stop(request));
        }

        Sent.Add(request);
        if (Sent.OfType<StopRequest>().Any() && FailureAfterStop is { } failure)
        {
            return Task.FromResult<LinkReply>(new LinkReply.Failed(failure, Sent: true));
        }

        if (InStop)
        {
            return Task.FromResult<LinkReply>(new LinkReply.Failed(
                new PlcCommunicationException(PlcErrorKind.NoAnswer, station, $"{station} on fake: no valid reply to {request.Command} after 2 attempts"), Sent: true));
        }

        return Task.FromResult<LinkReply>(new LinkReply.Answered(request switch
        {
            IdentifyRequest => Identity(request.Sequence),
            _ => new ErrorResponse(station, request.Sequence, request.Command, ProtocolError.UnknownCommand),
        }));
    }

    public LinkStatistics StatisticsFor(Station s) => LinkStatistics.Empty;

    /// <summary>STOP meets its <see cref="Fate"/>, sent once as the link sends a request that acts on the process.</summary>
    private LinkReply Stop(PlcRequest request)
    {
        if (Fate == StopFate.NeverSent)
        {
            return new LinkReply.Failed(new PlcCommunicationException(PlcErrorKind.PortUnavailable, station, "COM9 is gone"), Sent: false);
        }

        Sent.Add(request);
        InStop = Fate is StopFate.Executed or StopFate.ExecutedReplyLost;
        return Fate switch
        {
            StopFate.Executed or StopFate.AcknowledgedButRunning => new LinkReply.Answered(new StopResponse(station, request.Sequence)),
            StopFate.ExecutedReplyLost or StopFate.RequestLost =>
                new LinkReply.Failed(new PlcCommunicationException(PlcErrorKind.NoAnswer, station, "no reply within 120 ms"), Sent: true),
            StopFate.Refused => new LinkReply.Answered(new ErrorResponse(station, request.Sequence, CommandCode.Stop, ProtocolError.UnknownCommand)),
            StopFate.NeverSent => throw new InvalidOperationException("handled above"),
        };
    }

    /// <summary>A CPU 224 handler (docs/protocol-v2.md worked example) with this link's FEATURES.</summary>
    private IdentifyResponse Identity(byte sequence) =>
        new(station, sequence, 2, 1, 3, 1, 0x3C, 116, 5, 0x20, 1, 3, 2, 9, 0, 7764, 428, features, 120);
}
