namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// One RS-485 bus with several stations: every byte reaches every port, and only the addressed station answers
/// (seed 003: 18 S7-200s on one bus). A reply is on the bus too, so it lands in every other station's buffer
/// (docs/protocol-v2.md 1.6, invalidation 1: a long reply of one station clears another's lists). Replies come back in the
/// order the stations were attached.
/// </summary>
public sealed class BusSimulator
{
    private readonly List<SimulatedPlcPort> _ports = [];

    public IReadOnlyList<SimulatedPlcPort> Ports => _ports;

    public SimulatedPlcPort Attach(ReferencePlc plc)
    {
        var port = new SimulatedPlcPort(plc);
        _ports.Add(port);
        return port;
    }

    public IReadOnlyList<byte[]> Feed(ReadOnlySpan<byte> bytes)
    {
        var replies = new List<byte[]>();
        foreach (var port in _ports)
        {
            foreach (var reply in port.Feed(bytes))
            {
                replies.Add(reply);
                foreach (var other in _ports.Where(p => p != port))
                {
                    replies.AddRange(other.Feed(reply));
                }
            }
        }

        return replies;
    }
}
