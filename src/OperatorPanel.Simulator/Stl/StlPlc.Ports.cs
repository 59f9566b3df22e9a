namespace OperatorPanel.Simulator.Stl;

/// <summary>RCV/XMT hand the V buffer to the port; port and timed events are collected whenever one is due.</summary>
public sealed partial class StlPlc
{
    /// <summary>RCV TBL, PORT / XMT TBL, PORT. A port the host did not attach is a port with nothing connected: no-op.</summary>
    private void PortInstruction(StlOp op)
    {
        if (_ports[op.N] is not { } port || !TrySpan(op.A!, 1, out var area, out var offset))
        {
            return;
        }

        if (!ReferenceEquals(area, Memory.V))
        {
            Failed("PortBuffer", "the simulator's ports take RCV/XMT buffers in V memory only");
            return;
        }

        // The port acts at the time it was last advanced to (FreeportPort), so bring it to this instruction's time first:
        // otherwise an XMT long after the port's last change would date its characters back to that change.
        AdvancePort(port);
        if (op.Code == StlOpCode.Rcv)
        {
            port.Receive(offset);
        }
        else
        {
            port.Transmit(offset);
        }

        RefreshNextChange();
    }

    private void AdvancePort(IStlPort port)
    {
        _raised.Clear();
        port.AdvanceTo(TimeSpan.FromTicks(_now / 100), _raised);
        foreach (var raised in _raised)
        {
            Enqueue(raised.Number, raised.At.Ticks * 100);
        }
    }

    private void CollectEvents()
    {
        var now = TimeSpan.FromTicks(_now / 100);
        foreach (var port in _ports)
        {
            if (port?.NextChange is { } change && change <= now)
            {
                AdvancePort(port);
            }
        }

        for (var timer = 0; timer < 2; timer++)
        {
            while (_timedNext[timer] <= _now)
            {
                Enqueue(10 + timer, _timedNext[timer]);
                _timedNext[timer] += _timedInterval[timer];
            }
        }

        RefreshNextChange();
    }

    private void RefreshNextChange()
    {
        var next = Math.Min(_timedNext[0], _timedNext[1]);
        foreach (var port in _ports)
        {
            if (port?.NextChange is { } change)
            {
                next = Math.Min(next, change.Ticks * 100);
            }
        }

        _nextChange = next;
    }
}
