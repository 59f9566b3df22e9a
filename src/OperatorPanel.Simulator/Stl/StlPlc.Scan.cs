using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Execution;
using OperatorPanel.Simulator.Stl.Operations;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The scan cycle in simulated time: read inputs, OB1, then the housekeeping overhead (communication, write outputs);
/// interrupts are serviced between instructions and during the overhead. SMB0 and SMW22-SMW26 per seed 002,
/// Tables C-1 and C-9.
/// </summary>
public sealed partial class StlPlc
{
    private const long Millisecond = StlTime.Millisecond;

    /// <summary>Scan watchdog: the S7-200 goes to STOP when a scan exceeds 500 ms (unconfirmed in our sources).</summary>
    private const long Watchdog = 500 * Millisecond;

    private long _scanStart;
    private long _scanBusyStart;
    private long _overheadUntil;
    private long _userProgramLeft;
    private bool _firstScan;
    private bool _scanClock;
    private int _minScan = int.MaxValue;
    private int _maxScan;
    private StlRunningInterrupt _interrupt;

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
    /// When the main program last ended (its last instruction, END or MEND; the outputs are written then), in ns; null
    /// before the first scan ends. Exact to the ns, so <see cref="RunTo"/> can come back to it.
    /// </summary>
    internal long? LastProgramEnd { get; private set; }

    /// <summary>Executes scans and interrupts until simulated time <paramref name="until"/>; in STOP time passes, with the ports
    /// and the communication phase running when anything listens to it (<see cref="CommunicationPhase"/>).</summary>
    public void RunUntil(TimeSpan until) => RunTo(StlTime.FromTimeSpan(until));

    /// <summary><see cref="RunUntil"/> to a time in ns: the loop stops once the clock reaches <paramref name="end"/>.</summary>
    internal void RunTo(long end)
    {
        var time = _m.Time;
        _m.Events.InputsSet(InputImage[0], time.Now, Mode == OperatingMode.Run);
        _m.Events.Refresh();
        while (time.Now < end)
        {
            if (Mode == OperatingMode.Stop)
            {
                RunStopped(end);
                continue;
            }

            if (time.Now >= _m.Events.NextChange)
            {
                _m.Events.Collect(time.Now);
            }

            if (_m.Calls.InterruptBase < 0 && _m.Interrupts.Enabled && _m.Interrupts.HasQueued)
            {
                StartInterrupt();
            }
            else if (!_m.Calls.IsEmpty)
            {
                Step();
            }
            else if (_userProgramLeft > 0)
            {
                RunUserProgram(end);
            }
            else if (time.Now < _overheadUntil)
            {
                time.Now = Math.Min(Math.Min(_overheadUntil, _m.Events.NextChange), end);
            }
            else
            {
                BeginScan();
            }
        }

        time.Now = Math.Max(time.Now, end);
    }

    private void Step()
    {
        ref var frame = ref _m.Calls.Current;
        var ops = frame.Block.Ops;
        if (frame.Pc >= ops.Length)
        {
            _m.Return();
            return;
        }

        var op = ops[frame.Pc++];
        _m.Op = op;
        InstructionsExecuted++;
        _blockInstructions[frame.Block.Index]++;
        _m.Time.Spend(Execute(op));
        if (_m.Fault is not null)
        {
            EnterStop(_m.Fault);
        }
        else if (_m.Time.Now - _m.WatchdogFrom > Watchdog)
        {
            _m.Fail("Watchdog", "the scan took longer than 500 ms");
            EnterStop(_m.Fault);
        }
    }

    /// <summary>Runs one instruction by its row of the table; returns its time in ns.</summary>
    private long Execute(StlOp op)
    {
        var operation = op.Operation;
        if (operation.Flow == StlPowerFlow.Required)
        {
            if (!_m.Logic.Top)
            {
                _m.Eno = false;
                return operation.Unpowered?.Invoke(_m, op) ?? StlTiming.WithoutPowerFlow;
            }

            _m.Eno = true;
        }

        operation.Execute(_m, op);
        return op.Cost + _m.TakeCharge();
    }

    private void BeginScan()
    {
        var now = _m.Time.Now;
        if (!_firstScan)
        {
            var scan = (int)Math.Min((now - _scanStart) / Millisecond, ushort.MaxValue);
            _minScan = Math.Min(_minScan, scan);
            _maxScan = Math.Max(_maxScan, scan);
            Memory.WriteWord(ProtocolArea.SM, 22, (ushort)scan);
            Memory.WriteWord(ProtocolArea.SM, 24, (ushort)_minScan);
            Memory.WriteWord(ProtocolArea.SM, 26, (ushort)_maxScan);
            ScanCompleted?.Invoke(this, new StlScan(StlTime.ToTimeSpan(_scanStart), StlTime.ToTimeSpan(now), StlTime.ToTimeSpan(_m.Time.Busy - _scanBusyStart)));
        }

        _scanStart = now;
        _m.WatchdogFrom = now;
        _scanBusyStart = _m.Time.Busy;
        _m.Timers.CountTenMillisecondTimers();
        Array.Copy(InputImage, Memory.I, Memory.I.Length);
        _scanClock = !_scanClock;
        Memory.SM[0] = (byte)(0x01
            | (_firstScan ? 0x02 | 0x08 : 0)
            | ((now / (30_000 * Millisecond)) % 2 == 0 ? 0x10 : 0)
            | ((now / (500 * Millisecond)) % 2 == 0 ? 0x20 : 0)
            | (_scanClock ? 0x40 : 0)
            | (ModeSwitch == ModeSwitch.Run ? 0x80 : 0));
        if (_firstScan)
        {
            (_minScan, _maxScan) = (int.MaxValue, 0);
        }

        _firstScan = false;
        Scans++;
        _m.Enter(_program.Blocks[0], 0);
    }

    /// <summary>OB1 ended (its last instruction, END or MEND): STOP if the program asked for it, else the user's program time.</summary>
    private void EndScan()
    {
        LastProgramEnd = _m.Time.Now;
        if (_m.StopRequest is { } stop)
        {
            _m.StopRequest = null;
            EnterStop(stop);
            return;
        }

        _userProgramLeft = StlTime.FromTimeSpan(UserProgramTime);
        if (_userProgramLeft == 0)
        {
            BeginOverhead();
        }
    }

    /// <summary>The user's program time up to the next port or timer event (an interrupt may be due then) or <paramref name="end"/>.</summary>
    private void RunUserProgram(long end)
    {
        var step = Math.Min(_userProgramLeft, Math.Max(Math.Min(_m.Events.NextChange, end) - _m.Time.Now, 0));
        _m.Time.Spend(step);
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
        _overheadUntil = _m.Time.Now + StlTiming.ScanOverhead;
        _m.Time.Busy += StlTiming.ScanOverhead;
    }

    private void StartInterrupt()
    {
        var queued = _m.Interrupts.TakeNext();
        _m.Time.Spend(StlTiming.InterruptOverhead);
        _interrupt = new StlRunningInterrupt(queued, _m.Time.Now, InstructionsExecuted, _m.Calls.NextLine());
        _m.SaveForInterrupt();
        _m.Enter(_program.Blocks[queued.Block], StlCallStack.InterruptLBase);
        _m.Calls.InterruptBase = _m.Calls.Depth;
    }

    private void FinishInterrupt()
    {
        _m.Calls.InterruptBase = -1;
        _m.RestoreAfterInterrupt();
        _m.Interrupts.ClearOverflowOfEmptyQueues();
        var queued = _interrupt.Event;
        InterruptServed?.Invoke(this, new StlInterruptRun(
            _program.Blocks[queued.Block].Name, queued.Event, StlTime.ToTimeSpan(queued.At), StlTime.ToTimeSpan(_interrupt.StartedAt),
            Now, InstructionsExecuted - _interrupt.InstructionsBefore, _interrupt.InterruptedLine));
    }
}
