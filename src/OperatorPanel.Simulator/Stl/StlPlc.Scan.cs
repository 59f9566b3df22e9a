using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The scan cycle in simulated time: read inputs, OB1, then the housekeeping overhead (communication, write outputs);
/// interrupts are serviced between instructions and during the overhead. SMB0 and SMW22-SMW26 per seed 002,
/// Tables C-1 and C-9.
/// </summary>
public sealed partial class StlPlc
{
    private const long Millisecond = 1_000_000;

    /// <summary>Scan watchdog: the S7-200 goes to STOP when a scan exceeds 500 ms (unconfirmed in our sources).</summary>
    private const long Watchdog = 500 * Millisecond;

    private long _now;
    private long _busy;
    private long _scanStart;
    private long _scanBusyStart;
    private long _overheadUntil;
    private long _userProgramLeft;
    private long _watchdogFrom;

    /// <summary>Set by STOP: the CPU finishes the scan, then goes to STOP (A5E00307987-04, "STOP" instruction).</summary>
    private StlFault? _stopRequest;
    private bool _firstScan;
    private bool _scanClock;
    private int _minScan = int.MaxValue;
    private int _maxScan;

    /// <summary>
    /// A user's own program beside the loaded one, as time per scan: it runs after OB1's loaded instructions (the
    /// generated handler asks to be network 1 of OB1), interrupts are served in it as between its instructions and
    /// lengthen it, and it counts in the scan's time (SMW22) and busy time. Zero: only the loaded program. The bench
    /// uses it for a line's program, which a real CPU reports in SMW22-SMW26.
    /// </summary>
    public TimeSpan UserProgramTime { get; set; }

    /// <summary>Raised at the start of each scan for the one before it (not for the first scan).</summary>
    public event EventHandler<StlScan>? ScanCompleted;

    /// <summary>
    /// Executes scans and interrupts until simulated time <paramref name="until"/>; in STOP time passes, with the ports
    /// and the communication phase running when anything listens to it (<see cref="CommunicationPhase"/>).
    /// </summary>
    public void RunUntil(TimeSpan until)
    {
        var end = until.Ticks * 100;
        RefreshNextChange();
        while (_now < end)
        {
            if (Mode == OperatingMode.Stop)
            {
                RunStopped(end);
                continue;
            }

            if (_now >= _nextChange)
            {
                CollectEvents();
            }

            if (_interruptBase < 0 && _interruptsEnabled && _queued > 0)
            {
                StartInterrupt();
            }
            else if (_depth >= 0)
            {
                Step();
            }
            else if (_userProgramLeft > 0)
            {
                RunUserProgram(end);
            }
            else if (_now < _overheadUntil)
            {
                _now = Math.Min(Math.Min(_overheadUntil, _nextChange), end);
            }
            else
            {
                BeginScan();
            }
        }

        _now = Math.Max(_now, end);
    }

    private void Step()
    {
        ref var frame = ref _frames[_depth];
        var ops = frame.Block.Ops;
        if (frame.Pc >= ops.Length)
        {
            Return();
            return;
        }

        var op = ops[frame.Pc++];
        _op = op;
        InstructionsExecuted++;
        _blockInstructions[frame.Block.Index]++;
        var cost = Execute(op);
        _now += cost;
        _busy += cost;
        if (Fault is not null)
        {
            EnterStop(Fault);
        }
        else if (_now - _watchdogFrom > Watchdog)
        {
            Failed("Watchdog", "the scan took longer than 500 ms");
            EnterStop(Fault);
        }
    }

    private void BeginScan()
    {
        if (!_firstScan)
        {
            var scan = (int)Math.Min((_now - _scanStart) / Millisecond, ushort.MaxValue);
            _minScan = Math.Min(_minScan, scan);
            _maxScan = Math.Max(_maxScan, scan);
            Memory.WriteWord(Core.Protocol.ProtocolArea.SM, 22, (ushort)scan);
            Memory.WriteWord(Core.Protocol.ProtocolArea.SM, 24, (ushort)_minScan);
            Memory.WriteWord(Core.Protocol.ProtocolArea.SM, 26, (ushort)_maxScan);
            ScanCompleted?.Invoke(this, new StlScan(TimeSpan.FromTicks(_scanStart / 100), TimeSpan.FromTicks(_now / 100), TimeSpan.FromTicks((_busy - _scanBusyStart) / 100)));
        }

        _scanStart = _now;
        _watchdogFrom = _now;
        _scanBusyStart = _busy;
        CountTenMillisecondTimers();
        Array.Copy(InputImage, Memory.I, Memory.I.Length);
        _scanClock = !_scanClock;
        Memory.SM[0] = (byte)(0x01
            | (_firstScan ? 0x02 | 0x08 : 0)
            | ((_now / (30_000 * Millisecond)) % 2 == 0 ? 0x10 : 0)
            | ((_now / (500 * Millisecond)) % 2 == 0 ? 0x20 : 0)
            | (_scanClock ? 0x40 : 0)
            | (ModeSwitch == ModeSwitch.Run ? 0x80 : 0));
        if (_firstScan)
        {
            (_minScan, _maxScan) = (int.MaxValue, 0);
        }

        _firstScan = false;
        Scans++;
        Push(_program.Blocks[0], 0, null);
    }

    private void EndScan()
    {
        if (_stopRequest is { } stop)
        {
            _stopRequest = null;
            EnterStop(stop);
            return;
        }

        _userProgramLeft = UserProgramTime.Ticks * 100;
        if (_userProgramLeft == 0)
        {
            BeginOverhead();
        }
    }

    /// <summary>The user's program time up to the next port or timer event (an interrupt may be due then) or <paramref name="end"/>.</summary>
    private void RunUserProgram(long end)
    {
        var step = Math.Min(_userProgramLeft, Math.Max(Math.Min(_nextChange, end) - _now, 0));
        _now += step;
        _busy += step;
        _userProgramLeft -= step;
        if (_userProgramLeft == 0)
        {
            BeginOverhead();
        }
    }

    private void BeginOverhead()
    {
        Array.Copy(Memory.Q, OutputImage, OutputImage.Length);
        ServeCommunication();
        _overheadUntil = _now + StlTiming.ScanOverhead;
        _busy += StlTiming.ScanOverhead;
    }
}
