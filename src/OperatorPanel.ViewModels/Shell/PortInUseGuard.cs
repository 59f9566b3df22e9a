using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Transport;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>
/// "Test connection" while the panel is connected: a serial port can be opened only once, and a second link on the
/// same RS-485 bus would garble the running poll. So a test of a port the session is using is refused with a message
/// telling the operator to disconnect first (the session is not disconnected behind their back); other ports are tested.
/// </summary>
public sealed class PortInUseGuard : IConnectionTester
{
    private readonly IConnectionTester _inner;
    private readonly PanelSession _session;

    public PortInUseGuard(IConnectionTester inner, PanelSession session)
    {
        ArgumentNullException.ThrowIfNull(inner);
        ArgumentNullException.ThrowIfNull(session);
        (_inner, _session) = (inner, session);
    }

    public Task<LinkReply> IdentifyAsync(SerialSettings link, Station station, CancellationToken cancellationToken) =>
        InUse(link) is { } inUse
            ? Task.FromResult<LinkReply>(new LinkReply.Failed(new PlcCommunicationException(PlcErrorKind.PortUnavailable, station, inUse), Sent: false))
            : _inner.IdentifyAsync(link, station, cancellationToken);

    public Task<PpiIdentifyOutcome> IdentifyPpiAsync(SerialSettings link, Station station, CancellationToken cancellationToken) =>
        InUse(link) is { } inUse
            ? Task.FromResult(new PpiIdentifyOutcome(null, inUse))
            : _inner.IdentifyPpiAsync(link, station, cancellationToken);

    /// <summary>Why the port may not be tested now; null when it may.</summary>
    private string? InUse(SerialSettings link)
    {
        ArgumentNullException.ThrowIfNull(link);
        return _session.IsConnected && _session.Project.Stations.Any(s => string.Equals(s.Link.PortName, link.PortName, StringComparison.OrdinalIgnoreCase))
            ? $"the panel is connected on {link.PortName}; choose Disconnect in the main window, then test again"
            : null;
    }
}
