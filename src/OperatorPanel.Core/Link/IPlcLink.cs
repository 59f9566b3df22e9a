using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Request/response to the stations of one bus, with retries. The readers and writers of the polling loop talk to this;
/// <see cref="PlcLink"/> implements it over a <see cref="Transport.ITransport"/>. Not for concurrent callers: its bus
/// (Line/Bus) is its one user and puts one request on the wire at a time.
/// </summary>
public interface IPlcLink
{
    /// <summary>
    /// Sends <paramref name="request"/> under the link's next sequence number and returns the matching reply (an
    /// <see cref="ErrorResponse"/> included) or, when no valid reply came after the retries, the failure. A request
    /// that acts on the process (<see cref="PlcLink.ActsOnProcess"/>) is sent once, never repeated; its failure says
    /// whether the frame left the PC. Throws only when cancelled.
    /// </summary>
    Task<LinkReply> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken);

    /// <summary>Counters and round-trip times per station since the link was created.</summary>
    LinkStatistics StatisticsFor(Station station);
}
