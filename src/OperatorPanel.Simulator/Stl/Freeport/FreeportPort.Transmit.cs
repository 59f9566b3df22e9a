namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>XMT: buffer bytes 1..count leave one character time apart; count 0 sends a break (facts section 8).</summary>
public sealed partial class FreeportPort
{
    private readonly List<WireCharacter> _transmitted = [];
    private Transmission? _transmission;

    /// <summary>Every character this port finished sending since the last call, in order, with its completion time.</summary>
    public IReadOnlyList<WireCharacter> TakeTransmitted()
    {
        var taken = _transmitted.ToArray();
        _transmitted.Clear();
        return taken;
    }

    public void Transmit(int bufferOffset)
    {
        if (!TryEnterFreeport())
        {
            return;
        }

        LastFault = FreeportFault.None;
        if (_receive is not null)
        {
            LastFault = FreeportFault.SimultaneousTransmitReceive;
            return;
        }

        if (_transmission is not null)
        {
            LastFault = FreeportFault.TransmitterBusy;
            return;
        }

        var v = _memory.V;
        if (bufferOffset < 0 || bufferOffset >= v.Length || bufferOffset + v[bufferOffset] >= v.Length)
        {
            LastFault = FreeportFault.BufferOutOfRange;
            return;
        }

        var count = v[bufferOffset];
        var burst = new WireBurst(_now, Line, isBreak: count == 0);
        if (count > 0)
        {
            burst.Append(v.AsSpan(bufferOffset + 1, count));
        }

        _transmission = new Transmission(burst);
        SetTransmitterIdle(false);
        Bus?.Forward(this, burst);
    }

    private void SendNext(ICollection<StlEvent> raised)
    {
        var transmission = _transmission!;
        var at = transmission.NextAt;
        var burst = transmission.Burst;
        _transmitted.Add(burst.IsBreak ? new WireCharacter(0, at, IsBreak: true) : new WireCharacter(burst[transmission.Sent], at, IsPpi: transmission.IsPpi));
        if (!transmission.IsLast)
        {
            transmission.Sent++;
            return;
        }

        _transmission = null;
        if (!transmission.IsPpi)
        {
            SetTransmitterIdle(true);
            raised.Add(new StlEvent(_registers.TransmitCompleteEvent, at));
        }
    }

    /// <summary>SM4.5 (port 0) / SM4.6 (port 1): transmitter idle (seed 002, Table C-5).</summary>
    private void SetTransmitterIdle(bool idle)
    {
        var mask = (byte)(1 << _registers.TransmitIdleBit);
        var queue = _memory.SM[PortRegisters.QueueByte];
        _memory.SM[PortRegisters.QueueByte] = (byte)(idle ? queue | mask : queue & ~mask);
    }
}
