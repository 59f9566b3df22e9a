using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link.V3;

/// <summary>
/// What one v3 exchange brought (<see cref="V3Link.ExchangeV3Async"/>): the reply whose REQCHECK is the request's (an
/// error reply included), or why none came. <see cref="Sent"/> false: the frame never left the PC.
/// <see cref="CorruptedCopy"/>: a well-formed reply that was no refusal answered another frame than ours, so the PLC may
/// have acted on a copy of the request that noise changed.
/// </summary>
public sealed record V3Exchange(Reply? Reply, PlcCommunicationException? Failure, bool Sent = true, bool CorruptedCopy = false)
{
    public static V3Exchange Answered(Reply reply) => new(reply, null);

    public static V3Exchange Failed(PlcCommunicationException failure, bool sent, bool corruptedCopy = false) => new(null, failure, sent, corruptedCopy);
}
