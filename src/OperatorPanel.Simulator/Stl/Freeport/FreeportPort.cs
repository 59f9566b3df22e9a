using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// Port 0 or 1 of a simulated S7-200 in Freeport mode, in simulated time (TimeSpan since power-up; no clocks, no
/// threads). The host puts the PC's characters on the line with <see cref="Deliver"/> and collects the port's with
/// <see cref="TakeTransmitted"/>; the STL engine calls <see cref="Receive"/>/<see cref="Transmit"/> and drives time
/// with <see cref="AdvanceTo"/>. RCV and XMT act at the time of the last AdvanceTo, so the engine advances the port to
/// the instruction's time first.
/// <para>Line: settings come from SMB30/SMB130 when RCV or XMT runs (<see cref="LineSettings.TryFromControlByte"/>);
/// characters travel at that baud and a PC with other settings is received garbled (<see cref="WireInput"/>).</para>
/// <para>PPI and STOP: the port is in Freeport only from an RCV or XMT with mm = 01 until mm is written back to 00/10/11
/// (seen at the next AdvanceTo) or <see cref="Reset"/> (the CPU left RUN). In PPI, RCV and XMT do nothing but set
/// <see cref="LastFault"/> = NotFreeport (the S7-200 ends the box with ENO = 0); SMB86 is left alone, no event is raised,
/// and arriving characters are lost (<see cref="LostCharacters"/>). Leaving Freeport ends a receive without status or
/// event and stops a transmission after the character on the wire.</para>
/// <para>Half duplex (seed 001 "avoiding the simultaneous execution of XMT and RCV"; facts section 8, error 0009/000B):
/// XMT while a receive is enabled and RCV while transmitting are refused with
/// <see cref="FreeportFault.SimultaneousTransmitReceive"/> and the running operation carries on. To answer, a handler
/// lets the receive end (event 23/24), XMTs, and RCVs again on transmit complete (event 9/26).</para>
/// <para>RCV with en = 0 ends an active receive with status n and event 23/24 at that time; with no receive active it
/// does nothing. RCV with en = 1 while a receive is active is ignored (<see cref="FreeportFault.ReceiveAlreadyActive"/>).
/// An invalid set-up sets SMB86 = r (16#40) and starts nothing, without an event.</para>
/// </summary>
public sealed partial class FreeportPort : IStlPort
{
    private readonly PlcMemory _memory;
    private readonly CpuProfile _cpu;
    private readonly PortRegisters _registers;
    private readonly WireInput _input = new();
    private readonly WireSender _pc;
    private readonly List<StlEvent> _pending = [];
    private TimeSpan _now;
    private TimeSpan _readyAt;

    /// <summary>
    /// Port <paramref name="number"/> (0, or 1 on CPUs with two ports) working on <paramref name="memory"/> (SM and V)
    /// with <paramref name="cpu"/>'s baud codes; <paramref name="pcLine"/> is the PC side's setting for
    /// <see cref="Deliver"/> (e.g. <see cref="LineSettings.From"/> the project's SerialSettings).
    /// </summary>
    public FreeportPort(int number, PlcMemory memory, CpuProfile cpu, LineSettings pcLine)
    {
        ArgumentNullException.ThrowIfNull(memory);
        ArgumentNullException.ThrowIfNull(cpu);
        ArgumentOutOfRangeException.ThrowIfNegative(number);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(number, cpu.CommunicationPorts);
        Number = number;
        _memory = memory;
        _cpu = cpu;
        _registers = PortRegisters.For(number);
        _pc = new WireSender(pcLine);
        Line = pcLine;
        SetTransmitterIdle(true);
    }

    public int Number { get; }

    /// <summary>True from an RCV/XMT with SMB30 mm = 01 until PPI again (mode bits rewritten, or <see cref="Reset"/>).</summary>
    public bool IsFreeport { get; private set; }

    /// <summary>The settings latched from SMB30/SMB130 by the last RCV or XMT in Freeport (the PC's until then).</summary>
    public LineSettings Line { get; private set; }

    public FreeportFault LastFault { get; private set; }

    /// <summary>Characters that arrived while no receive was active, or in PPI (diagnostics).</summary>
    public int LostCharacters { get; private set; }

    public bool IsReceiving => _receive is not null;

    public bool IsTransmitting => _transmission is not null;

    /// <summary>The time the port was last advanced to.</summary>
    public TimeSpan Now => _now;

    /// <summary>Set by <see cref="FreeportBus.Attach"/>: this port's transmissions reach the bus's other ports.</summary>
    internal FreeportBus? Bus { get; set; }

    public TimeSpan? NextChange
    {
        get
        {
            if (_pending.Count > 0)
            {
                return _now;
            }

            return Earliest(Earliest(PeekCharacter()?.At, _receive?.Deadline), _transmission?.NextAt);
        }
    }

    /// <summary>The PC sends <paramref name="characters"/> from <paramref name="at"/>, back to back after any still arriving.</summary>
    public void Deliver(ReadOnlySpan<byte> characters, TimeSpan at) => Accept(_pc.Send(characters, at));

    /// <summary>The PC holds the line low for 16 bit times from <paramref name="at"/> (a break, for bk start detection).</summary>
    public void DeliverBreak(TimeSpan at) => Accept(_pc.SendBreak(at));

    public void AdvanceTo(TimeSpan now, ICollection<StlEvent> raised)
    {
        ArgumentNullException.ThrowIfNull(raised);
        ArgumentOutOfRangeException.ThrowIfLessThan(now, _now);
        FollowModeBits();
        foreach (var pending in _pending)
        {
            raised.Add(pending);
        }

        _pending.Clear();
        while (Step(now, raised))
        {
        }

        _now = now;
        _input.Prune(_readyAt);
    }

    public void Reset()
    {
        LeaveFreeport();
        _pending.Clear();
    }

    internal void Accept(WireBurst burst) => _input.Add(burst);

    private static TimeSpan? Earliest(TimeSpan? a, TimeSpan? b) => a is null ? b : b is null ? a : a < b ? a : b;

    /// <summary>Handles the earliest of: a character received, the receive timer, a character sent; false when none is due.</summary>
    private bool Step(TimeSpan now, ICollection<StlEvent> raised)
    {
        var character = PeekCharacter();
        var deadline = _receive?.Deadline;
        var sent = _transmission?.NextAt;
        var next = Earliest(Earliest(character?.At, deadline), sent);
        if (next is not { } at || at > now)
        {
            return false;
        }

        if (character is { } c && c.At == at)
        {
            TakeCharacter(c, raised);
        }
        else if (deadline == at)
        {
            EndReceive(ReceiveStatus.TimerExpired, at, raised);
        }
        else
        {
            SendNext(raised);
        }

        return true;
    }

    private void FollowModeBits()
    {
        if (IsFreeport && !LineSettings.TryFromControlByte(_memory.SM[_registers.Control], _cpu, out _))
        {
            LeaveFreeport();
        }
    }

    /// <summary>RCV and XMT read SMB30/SMB130 to switch to Freeport and latch the line settings.</summary>
    private bool TryEnterFreeport()
    {
        if (!LineSettings.TryFromControlByte(_memory.SM[_registers.Control], _cpu, out var line))
        {
            LeaveFreeport();
            LastFault = FreeportFault.NotFreeport;
            return false;
        }

        if (!IsFreeport)
        {
            _ppiReader.Reset();
        }

        IsFreeport = true;
        Line = line;
        return true;
    }

    private void LeaveFreeport()
    {
        IsFreeport = false;
        _receive = null;
        if (_transmission is { IsPpi: false } transmission)
        {
            transmission.Burst.DropFrom(_now);
            _transmission = null;
        }

        SetTransmitterIdle(true);
    }
}
