using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Line;

/// <summary>
/// The Freeport link of a PPI bus: there is none, so a Freeport request (an IDENTIFY from a window that asks every bus)
/// fails here, before anything is sent, instead of putting a frame the CPU cannot read on its wire.
/// </summary>
internal sealed class FreeportRefusedLink(string portName) : IPlcLink
{
    public Task<LinkReply> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(request);
        var failure = new PlcCommunicationException(PlcErrorKind.NegativeReply, request.Station,
            $"{portName} is a PPI bus: the panel sends no Freeport {request.Command} on it (docs/ppi.md)");
        return Task.FromResult<LinkReply>(new LinkReply.Failed(failure, Sent: false));
    }

    public LinkStatistics StatisticsFor(Station station) => LinkStatistics.Empty;
}
