using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link;

/// <summary>
/// What became of a request that acts on the process (WRITE, WRITE BIT, STOP), sent at most once: it is never resent
/// after the PLC may have acted on it, because a repeat can act twice (a start bit the PLC program resets at once).
/// </summary>
public abstract record OnceReply
{
    private OnceReply()
    {
    }

    /// <summary>A reply that answers exactly the frame sent (an error reply included).</summary>
    public sealed record Answered(PlcResponse Response) : OnceReply;

    /// <summary>The frame never left the PC (the port could not be opened): the PLC did nothing.</summary>
    public sealed record NotSent(PlcCommunicationException Failure) : OnceReply;

    /// <summary>
    /// The frame went out and no reply answering it came: a timeout, a garbled reply, or (<paramref name="CorruptedCopy"/>)
    /// a reply whose REQCHECK shows the PLC acted on a corrupted copy of the request. The PLC may have acted.
    /// </summary>
    public sealed record ReplyLost(string Cause, bool CorruptedCopy) : OnceReply;
}
