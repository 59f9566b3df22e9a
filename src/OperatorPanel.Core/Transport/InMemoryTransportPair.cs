namespace OperatorPanel.Core.Transport;

/// <summary>
/// Two connected in-memory transports, a null-modem cable without a line: what <see cref="PanelSide"/> writes,
/// <see cref="BusSide"/> reads, and back. Demo mode puts simulated stations on the bus side; tests drive read
/// timeouts with a manual <see cref="TimeProvider"/>, so no test waits in real time. Closing either end makes every
/// later read and write on both fail as PortUnavailable, like an unplugged adapter.
/// </summary>
public sealed class InMemoryTransportPair
{
    public InMemoryTransportPair(TimeProvider timeProvider, string panelName = "memory:panel", string busName = "memory:bus")
    {
        ArgumentNullException.ThrowIfNull(timeProvider);
        var toBus = new InMemoryLine();
        var toPanel = new InMemoryLine();
        PanelSide = new InMemoryTransport(panelName, timeProvider, incoming: toPanel, outgoing: toBus);
        BusSide = new InMemoryTransport(busName, timeProvider, incoming: toBus, outgoing: toPanel);
    }

    /// <summary>The PC's end, for the link.</summary>
    public InMemoryTransport PanelSide { get; }

    /// <summary>The stations' end, for simulated PLCs.</summary>
    public InMemoryTransport BusSide { get; }
}
