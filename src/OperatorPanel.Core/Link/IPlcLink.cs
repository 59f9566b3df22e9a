using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Request/response to the stations of one bus, one request in flight at a time, with retries. The polling engine talks
/// to this; PlcLink implements it over an <see cref="Transport.ITransport"/>.
/// </summary>
public interface IPlcLink
{
    /// <summary>
    /// Sends <paramref name="request"/> under the link's next sequence number and returns the matching reply (an <see cref="ErrorResponse"/> included). Throws
    /// <see cref="Transport.PlcCommunicationException"/> when no valid reply came after the retries.
    /// </summary>
    Task<PlcResponse> ExchangeAsync(PlcRequest request, CancellationToken cancellationToken);

    /// <summary>Counters and round-trip times per station since the link was created.</summary>
    LinkStatistics StatisticsFor(Station station);

    /// <summary>Online after a valid reply; offline after a request that got none.</summary>
    bool IsOnline(Station station);
}
