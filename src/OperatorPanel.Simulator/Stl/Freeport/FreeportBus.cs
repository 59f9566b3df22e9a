namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// One RS-485 bus: the PC and one Freeport port per simulated station (seed 003: 18 S7-200s on one bus). What the PC
/// sends reaches every port; what a port sends reaches the PC and, as on RS-485, every other port too (a station does
/// not hear itself). Two talkers at once collide on the wire and the receivers decode garbage. The bus knows ports,
/// not PLCs: each station's engine still advances its own port; advance them in step (to the bus's
/// <see cref="NextChange"/>) so a station's reply reaches the others before they pass its time.
/// </summary>
public sealed class FreeportBus
{
    private readonly List<FreeportPort> _ports = [];
    private readonly WireSender _pc;

    public FreeportBus(LineSettings pcLine) => _pc = new WireSender(pcLine);

    public IReadOnlyList<FreeportPort> Ports => _ports;

    public LineSettings PcLine => _pc.Settings;

    /// <summary>The earliest <see cref="FreeportPort.NextChange"/> over all ports.</summary>
    public TimeSpan? NextChange
    {
        get
        {
            TimeSpan? next = null;
            foreach (var port in _ports)
            {
                next = port.NextChange is { } at && (next is null || at < next) ? at : next;
            }

            return next;
        }
    }

    public void Attach(FreeportPort port)
    {
        ArgumentNullException.ThrowIfNull(port);
        if (port.Bus is not null)
        {
            throw new InvalidOperationException($"Port {port.Number} is already on a bus.");
        }

        port.Bus = this;
        _ports.Add(port);
    }

    /// <summary>The PC sends <paramref name="characters"/> from <paramref name="at"/> to every station.</summary>
    public void Deliver(ReadOnlySpan<byte> characters, TimeSpan at) => Broadcast(_pc.Send(characters, at), from: null);

    public void DeliverBreak(TimeSpan at) => Broadcast(_pc.SendBreak(at), from: null);

    /// <summary>Every character the stations finished sending since the last call, in time order.</summary>
    public IReadOnlyList<WireCharacter> TakeTransmitted() =>
        [.. _ports.SelectMany(p => p.TakeTransmitted()).OrderBy(c => c.At)];

    internal void Forward(FreeportPort from, WireBurst burst) => Broadcast(burst, from);

    private void Broadcast(WireBurst burst, FreeportPort? from)
    {
        foreach (var port in _ports)
        {
            if (port != from)
            {
                port.Accept(burst);
            }
        }
    }
}
