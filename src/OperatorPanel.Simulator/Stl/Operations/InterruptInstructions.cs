using OperatorPanel.Simulator.Stl.Execution;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// ATCH, DTCH, ENI, DISI (C233-01 p. 9-165; docs/sources/s7200-facts.md section 5), and RCV/XMT, which hand a V buffer
/// to the port (section 8). ATCH's op.Target is the routine's block, op.N the event.
/// </summary>
internal static class InterruptInstructions
{
    public static void Attach(StlMachine m, StlOp op)
    {
        m.Interrupts.Attach(op.Target, op.N, m.Time.Now);
        m.Events.TimedAttached();
    }

    public static void Detach(StlMachine m, StlOp op) => m.Interrupts.Detach(op.N);

    public static void Enable(StlMachine m, StlOp op) => m.Interrupts.Enable(true);

    public static void Disable(StlMachine m, StlOp op) => m.Interrupts.Enable(false);

    public static void Receive(StlMachine m, StlOp op) => Port(m, op, receive: true);

    public static void Transmit(StlMachine m, StlOp op) => Port(m, op, receive: false);

    /// <summary>RCV TBL, PORT / XMT TBL, PORT. A port the host did not attach is a port with nothing connected: no-op.</summary>
    private static void Port(StlMachine m, StlOp op, bool receive)
    {
        if (m.Events.Port(op.N) is not { } port || !m.TrySpan(op.A!, 1, out var area, out var offset))
        {
            return;
        }

        if (!ReferenceEquals(area, m.Memory.V))
        {
            m.Fail("PortBuffer", "the simulator's ports take RCV/XMT buffers in V memory only");
            return;
        }

        // The port acts at the time it was last advanced to (FreeportPort), so bring it to this instruction's time first:
        // otherwise an XMT long after the port's last change would date its characters back to that change.
        m.Events.Advance(port, m.Time.Now);
        if (receive)
        {
            port.Receive(offset);
        }
        else
        {
            port.Transmit(offset);
        }

        m.Events.Refresh();
    }
}
