using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Execution;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The simulated S7-200 CPU executing a loaded STL program in simulated time: no clocks, no threads. The host
/// attaches ports, sets the input image and the mode switch, and calls <see cref="RunUntil"/>; each instruction
/// advances time by its execution time (Operations/StlOperations), so scan times and port timing interact. A run-time
/// error puts the CPU in STOP with a <see cref="Fault"/>; no exception reaches the host. This file is the host's side;
/// StlPlc.Scan.cs runs the scan cycle. What an instruction sees is the <see cref="StlMachine"/>.
/// </summary>
public sealed partial class StlPlc
{
    private readonly StlProgram _program;
    private readonly StlMachine _m;
    private readonly long[] _blockInstructions;

    public StlPlc(StlProgram program)
    {
        ArgumentNullException.ThrowIfNull(program);
        _program = program;
        Memory = new PlcMemory(program.Cpu);
        Memory.SM[6] = program.Cpu.CpuIdCode;
        _m = new StlMachine(program.Cpu, Memory, program.Blocks, program.EdgeCount)
        {
            MainEnded = EndScan,
            InterruptEnded = FinishInterrupt,
        };
        _blockInstructions = new long[program.Blocks.Length];
        EnterRun();
    }

    public CpuProfile Cpu => _program.Cpu;

    /// <summary>I, Q, M, V and SM, shared with ports and host code.</summary>
    public PlcMemory Memory { get; }

    /// <summary>The field inputs; copied into I at the start of each scan.</summary>
    public byte[] InputImage => _m.InputImage;

    /// <summary>The outputs as the field sees them: Q copied at the end of each scan, zero in STOP.</summary>
    public byte[] OutputImage => _m.OutputImage;

    public OperatingMode Mode { get; private set; }

    /// <summary>The mode switch position RUN or TERM, shown to the program as SM0.7.</summary>
    public ModeSwitch ModeSwitch { get; set; } = ModeSwitch.Run;

    /// <summary>Why the CPU stopped on its own; null while it runs or after a host STOP.</summary>
    public StlFault? Fault => _m.Fault;

    /// <summary>Simulated time since power-up.</summary>
    public TimeSpan Now => StlTime.ToTimeSpan(_m.Time.Now);

    public long InstructionsExecuted { get; private set; }

    /// <summary>Sum of the execution times of the instructions executed (and of interrupt entry and scan housekeeping).</summary>
    public TimeSpan ExecutionTime => StlTime.ToTimeSpan(_m.Time.Busy);

    public long Scans { get; private set; }

    /// <summary>The date and time the real-time clock shows at simulated time zero (TODR, TODW).</summary>
    public DateTime ClockStart
    {
        get => _m.Clock.Start;
        set => _m.Clock.Start = value;
    }

    /// <summary>What TODR reads now.</summary>
    public DateTime Clock => _m.Clock.Now;

    /// <summary>Raised after each interrupt routine run, with the instructions it executed.</summary>
    public event EventHandler<StlInterruptRun>? InterruptServed;

    /// <summary>Instructions executed in the named block (its own instructions, not its subroutines').</summary>
    public long InstructionsIn(string blockName) =>
        _blockInstructions[_program.Blocks.First(b => string.Equals(b.Name, blockName, StringComparison.OrdinalIgnoreCase)).Index];

    public uint Accumulator(int number) => _m.Accumulator(number);

    /// <summary>Connects a port; a CPU 221/222/224 has port 0 only, a 224XP/226 ports 0 and 1.</summary>
    public void AttachPort(IStlPort port) => _m.Events.AttachPort(port);

    /// <summary>STOP: ports back to PPI, nothing runs, outputs off.</summary>
    public void Stop() => EnterStop(null);

    /// <summary>RUN from STOP: the next scan is a first scan (SM0.1 on); a fault is cleared.</summary>
    public void Run()
    {
        if (Mode != OperatingMode.Run)
        {
            _m.Fault = null;
            EnterRun();
        }
    }

    /// <summary>The bytes of I, Q, M, V, SM, S, AI or AQ (I is the process image the program reads).</summary>
    public byte[] AreaBytes(MemoryArea area)
    {
        if (area is MemoryArea.T or MemoryArea.C or MemoryArea.AC or MemoryArea.HC or MemoryArea.L || _m.Area(area) is not { } bytes)
        {
            throw new ArgumentOutOfRangeException(nameof(area), area, "timers, counters, accumulators, HC and L are not byte areas");
        }

        return bytes;
    }

    /// <summary>Current value of Tn (0-32767), as the program would read it now.</summary>
    public short TimerCurrentValue(int timer) => _m.Timers.Value(timer);

    public bool TimerBitValue(int timer) => _m.Timers.Bit(timer);

    public short CounterCurrentValue(int counter) => _m.Counters.Value(counter);

    public bool CounterBitValue(int counter) => _m.Counters.Bit(counter);

    private void EnterRun()
    {
        Mode = OperatingMode.Run;
        _firstScan = true;
        _overheadUntil = _m.Time.Now;
        _userProgramLeft = 0;
        _m.Calls.Clear();
        _scanStart = _m.Time.Now;
    }

    private void EnterStop(StlFault? fault)
    {
        Mode = OperatingMode.Stop;
        _m.Fault = fault;
        _nextStopCycle = _m.Time.Now;
        _m.Calls.Clear();
        _m.Calls.InterruptBase = -1;
        _m.Interrupts.Reset();
        Array.Clear(OutputImage);
        _m.Events.ResetPorts();
    }
}
