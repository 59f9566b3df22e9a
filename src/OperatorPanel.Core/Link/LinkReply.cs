using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link;

/// <summary>
/// What one exchange brought, as a value. The link never throws a link failure: the transport's
/// <see cref="PlcCommunicationException"/> is caught in the link and carried here, so a failure keeps this one form from
/// the link through the readers to the station states (Polling/StationTracker).
/// </summary>
public abstract record LinkReply
{
    private LinkReply()
    {
    }

    /// <summary>The reply, when one answered exactly the frame sent (an error reply included); else null.</summary>
    public virtual PlcResponse? Response => null;

    /// <summary>Why no reply answered the frame; null when one did.</summary>
    public virtual PlcCommunicationException? Failure => null;

    /// <summary>A reply that answers exactly the frame sent (an error reply included).</summary>
    public sealed record Answered(PlcResponse Response) : LinkReply
    {
        public override PlcResponse Response { get; } = Response;
    }

    /// <summary>
    /// No reply answering the frame came. <paramref name="Sent"/> false: the frame never left the PC (the port could not
    /// be opened), so the PLC did nothing. <paramref name="CorruptedCopy"/>: a reply showed that the PLC acted on a copy
    /// of the request that noise changed (its REQCHECK was not the request's), so a write may have hit another address.
    /// </summary>
    public sealed record Failed(PlcCommunicationException Failure, bool Sent, bool CorruptedCopy = false) : LinkReply
    {
        public override PlcCommunicationException Failure { get; } = Failure;
    }
}
