using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Request/response to the stations of one bus, one request in flight at a time, with retries. The polling engine talks
/// to this; PlcLink implements it over an <see cref="Transport.ITransport"/>.
/// </summary>
public interface IPlcLink
{
    /// <summary>
    /// Sends <paramref name="request"/> under the link's next sequence number and returns the matching reply (an <see cref="ErrorResponse"/> included). Throws
    /// <see cref="PlcCommunicationException"/> when no valid reply came after the retries. A request that acts on
    /// the process (<see cref="PlcLink.ActsOnProcess"/>) gets no retries.
    /// </summary>
    Task<PlcResponse> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken);

    /// <summary>
    /// Sends a request that acts on the process once, never repeated, and says whether it was answered, never left the
    /// PC, or may have acted without an answer (the caller then reads the target back).
    /// </summary>
    Task<OnceReply> ExchangeOnceAsync(PlcRequest request, CancellationToken cancellationToken);

    /// <summary>Counters and round-trip times per station since the link was created.</summary>
    LinkStatistics StatisticsFor(Station station);

    /// <summary>Online after a valid reply; offline after a request that got none.</summary>
    bool IsOnline(Station station);
}
