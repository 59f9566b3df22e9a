namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// What raises interrupt events while the CPU runs: the communication ports (receive character, receive message
/// complete, transmit complete), the timed interrupts, and the edges of the field inputs I0.0-I0.3 (events 0-7,
/// ML801761 p. 172, Table 6-50: rising 0/2/4/6, falling 1/3/5/7). <see cref="NextChange"/> is when a port or timer
/// next needs the CPU's attention, so the scan loop looks at them only then; the inputs change only when the host sets
/// them, between runs.
/// </summary>
internal sealed class StlEventSources(StlInterrupts interrupts, int portCount)
{
    private readonly IStlPort?[] _ports = new IStlPort?[2];
    private readonly List<StlEvent> _raised = [];
    private int _edgeInputs;

    /// <summary>Simulated time (ns) of the next port or timed event; long.MaxValue when none is pending.</summary>
    public long NextChange { get; private set; } = long.MaxValue;

    /// <summary>A CPU 221/222/224 has port 0 only, a 224XP/226 ports 0 and 1.</summary>
    public void AttachPort(IStlPort port)
    {
        ArgumentNullException.ThrowIfNull(port);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(port.Number, portCount, nameof(port));
        ArgumentOutOfRangeException.ThrowIfNegative(port.Number, nameof(port));
        _ports[port.Number] = port;
        port.Reset();
    }

    /// <summary>The port RCV/XMT name; null when the host attached none (nothing connected).</summary>
    public IStlPort? Port(int number) => _ports[number];

    /// <summary>The CPU left RUN: every port ends its receive or transmit and speaks PPI again.</summary>
    public void ResetPorts()
    {
        foreach (var port in _ports)
        {
            port?.Reset();
        }
    }

    /// <summary>Brings a port to <paramref name="now"/>, queueing the events it raised on the way at their own times.</summary>
    public void Advance(IStlPort port, long now)
    {
        _raised.Clear();
        port.AdvanceTo(StlTime.ToTimeSpan(now), _raised);
        foreach (var raised in _raised)
        {
            interrupts.Enqueue(raised.Number, StlTime.FromTimeSpan(raised.At));
        }
    }

    /// <summary>Every port and timed event due by <paramref name="now"/> queued.</summary>
    public void Collect(long now)
    {
        AdvancePorts(now);
        interrupts.RaiseTimed(now);
        Refresh();
    }

    /// <summary>Every port whose next change is due by <paramref name="now"/> brought to it (the communication phase; STOP, where no timer runs).</summary>
    public void AdvancePorts(long now)
    {
        var time = StlTime.ToTimeSpan(now);
        foreach (var port in _ports)
        {
            if (port?.NextChange is { } change && change <= time)
            {
                Advance(port, now);
            }
        }
    }

    /// <summary>Simulated time (ns) a port next needs the CPU; long.MaxValue when none does.</summary>
    public long NextPortChange => _ports.Aggregate(long.MaxValue, (next, port) =>
        port?.NextChange is { } change ? Math.Min(next, StlTime.FromTimeSpan(change)) : next);

    public void Refresh()
    {
        var next = interrupts.NextTimed;
        foreach (var port in _ports)
        {
            if (port?.NextChange is { } change)
            {
                next = Math.Min(next, StlTime.FromTimeSpan(change));
            }
        }

        NextChange = next;
    }

    /// <summary>
    /// The field inputs as the host left them: each change of I0.0-I0.3 since the last look is an edge event at
    /// <paramref name="now"/> (queued when a routine is attached; <paramref name="raise"/> false in STOP, where only the
    /// new state is taken).
    /// </summary>
    public void InputsSet(byte firstInputByte, long now, bool raise)
    {
        var inputs = firstInputByte & 0x0F;
        var changed = inputs ^ _edgeInputs;
        _edgeInputs = inputs;
        for (var bit = 0; raise && bit < 4; bit++)
        {
            if ((changed & (1 << bit)) != 0)
            {
                interrupts.Enqueue((2 * bit) + ((inputs & (1 << bit)) != 0 ? 0 : 1), now);
            }
        }
    }

    /// <summary>A timed interrupt was just attached: it may fall due before anything else.</summary>
    public void TimedAttached() => NextChange = Math.Min(NextChange, interrupts.NextTimed);
}
