using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The simulated S7-200 CPU executing a loaded STL program in simulated time: no clocks, no threads. The host
/// attaches ports, sets the input image and the mode switch, and calls <see cref="RunUntil"/>; each instruction
/// advances time by its estimated execution time (<see cref="StlTiming"/>), so scan times and port timing interact.
/// A run-time error puts the CPU in STOP with a <see cref="Fault"/>; no exception reaches the host.
/// </summary>
public sealed partial class StlPlc
{
    /// <summary>
    /// Subroutine nesting: 8 levels from the main program, 4 from an interrupt routine, each level with its own 64 bytes
    /// of L ("Executing the user program" in the newer system manuals; the 1998 C233-01 manual allowed only one level
    /// from an interrupt routine, a limit the generated handler never reaches: it calls nothing from its routines).
    /// </summary>
    private const int MainNesting = 8;
    private const int InterruptNesting = 4;
    private const int LBytes = 64;
    private const int InterruptLBase = (MainNesting + 1) * LBytes;

    private readonly StlProgram _program;
    private readonly byte[][] _areas = new byte[(int)MemoryArea.L + 1][];
    private readonly byte[] _l = new byte[(MainNesting + InterruptNesting + 2) * LBytes];
    private readonly uint[] _ac = new uint[4];
    private readonly bool[] _edges;
    private readonly StlFrame[] _frames = new StlFrame[MainNesting + InterruptNesting + 2];
    private readonly long[] _blockInstructions;
    private readonly IStlPort?[] _ports = new IStlPort?[2];
    private int _depth = -1;
    private int _lBase;
    private uint _stack;
    private StlOp? _op;

    public StlPlc(StlProgram program)
    {
        ArgumentNullException.ThrowIfNull(program);
        _program = program;
        Memory = new PlcMemory(program.Cpu);
        _areas[(int)MemoryArea.I] = Memory.I;
        _areas[(int)MemoryArea.Q] = Memory.Q;
        _areas[(int)MemoryArea.M] = Memory.M;
        _areas[(int)MemoryArea.V] = Memory.V;
        _areas[(int)MemoryArea.SM] = Memory.SM;
        foreach (var area in new[] { MemoryArea.S, MemoryArea.AI, MemoryArea.AQ })
        {
            _areas[(int)area] = program.Cpu.TryGetArea(area, out var range) ? new byte[range.ByteCount] : [];
        }

        _edges = new bool[program.EdgeCount];
        _blockInstructions = new long[program.Blocks.Length];
        InputImage = new byte[Memory.I.Length];
        OutputImage = new byte[Memory.Q.Length];
        Memory.SM[6] = program.Cpu.CpuIdCode;
        InitialiseQueues();
        EnterRun();
    }

    public CpuProfile Cpu => _program.Cpu;

    /// <summary>I, Q, M, V and SM, shared with ports and host code.</summary>
    public PlcMemory Memory { get; }

    /// <summary>The field inputs; copied into I at the start of each scan.</summary>
    public byte[] InputImage { get; }

    /// <summary>The outputs as the field sees them: Q copied at the end of each scan, zero in STOP.</summary>
    public byte[] OutputImage { get; }

    public OperatingMode Mode { get; private set; }

    /// <summary>The mode switch position RUN or TERM, shown to the program as SM0.7.</summary>
    public ModeSwitch ModeSwitch { get; set; } = ModeSwitch.Run;

    /// <summary>Why the CPU stopped on its own; null while it runs or after a host STOP.</summary>
    public StlFault? Fault { get; private set; }

    /// <summary>Simulated time since power-up.</summary>
    public TimeSpan Now => TimeSpan.FromTicks(_now / 100);

    public long InstructionsExecuted { get; private set; }

    /// <summary>Sum of the estimated execution times of the instructions executed.</summary>
    public TimeSpan ExecutionTime => TimeSpan.FromTicks(_busy / 100);

    public long Scans { get; private set; }

    /// <summary>Raised after each interrupt routine run, with the instructions it executed.</summary>
    public event EventHandler<StlInterruptRun>? InterruptServed;

    /// <summary>Instructions executed in the named block (its own instructions, not its subroutines').</summary>
    public long InstructionsIn(string blockName) =>
        _blockInstructions[_program.Blocks.First(b => string.Equals(b.Name, blockName, StringComparison.OrdinalIgnoreCase)).Index];

    public uint Accumulator(int number) => _ac[number];

    /// <summary>Connects a port; a CPU 221/222/224 has port 0 only, a 224XP/226 ports 0 and 1.</summary>
    public void AttachPort(IStlPort port)
    {
        ArgumentNullException.ThrowIfNull(port);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(port.Number, Cpu.CommunicationPorts, nameof(port));
        ArgumentOutOfRangeException.ThrowIfNegative(port.Number, nameof(port));
        _ports[port.Number] = port;
        port.Reset();
    }

    /// <summary>STOP: ports back to PPI, nothing runs, outputs off.</summary>
    public void Stop() => EnterStop(null);

    /// <summary>RUN from STOP: the next scan is a first scan (SM0.1 on); a fault is cleared.</summary>
    public void Run()
    {
        if (Mode != OperatingMode.Run)
        {
            Fault = null;
            EnterRun();
        }
    }

    private void EnterRun()
    {
        Mode = OperatingMode.Run;
        _firstScan = true;
        _overheadUntil = _now;
        _userProgramLeft = 0;
        _depth = -1;
        _scanStart = _now;
    }

    private void EnterStop(StlFault? fault)
    {
        Mode = OperatingMode.Stop;
        Fault = fault;
        _nextStopCycle = _now;
        _depth = -1;
        _interruptBase = -1;
        ResetInterrupts();
        Array.Clear(OutputImage);
        foreach (var port in _ports)
        {
            port?.Reset();
        }
    }
}
