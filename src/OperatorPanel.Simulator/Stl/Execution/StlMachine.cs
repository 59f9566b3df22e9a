using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// What one instruction sees and changes: the memory areas, L memory, the accumulators, the logic stack, ENO and
/// SMB1, and the CPU's parts (timers, counters, call stack, interrupts, ports, clock). The rows of
/// <see cref="Operations.StlOperations"/> act on it; <see cref="StlPlc"/> runs the scan cycle around it. Three files:
/// this one (registers and faults), StlMachine.Operands.cs (reading and writing operands) and StlMachine.Calls.cs
/// (entering and leaving blocks).
/// </summary>
internal sealed partial class StlMachine
{
    /// <summary>L bytes per call level (facts doc section 1: 64 bytes of L per POU).</summary>
    public const int LBytes = 64;

    private readonly byte[][] _areas = new byte[(int)MemoryArea.L + 1][];
    private readonly byte[] _l = new byte[StlCallStack.Levels * LBytes];
    private readonly uint[] _ac = new uint[4];
    private readonly uint[] _savedAc = new uint[4];
    private readonly bool[] _edges;
    private long _charge;
    private byte _savedFlags;

    public StlMachine(CpuProfile cpu, PlcMemory memory, StlBlock[] blocks, int edgeCount)
    {
        Memory = memory;
        Blocks = blocks;
        _areas[(int)MemoryArea.I] = memory.I;
        _areas[(int)MemoryArea.Q] = memory.Q;
        _areas[(int)MemoryArea.M] = memory.M;
        _areas[(int)MemoryArea.V] = memory.V;
        _areas[(int)MemoryArea.SM] = memory.SM;
        foreach (var area in new[] { MemoryArea.S, MemoryArea.AI, MemoryArea.AQ })
        {
            _areas[(int)area] = cpu.TryGetArea(area, out var range) ? new byte[range.ByteCount] : [];
        }

        _edges = new bool[edgeCount];
        InputImage = new byte[memory.I.Length];
        OutputImage = new byte[memory.Q.Length];
        Timers = new StlTimers(Time);
        Clock = new StlRealTimeClock(Time);
        Interrupts = new StlInterrupts(cpu, memory.SM);
        Events = new StlEventSources(Interrupts, cpu.CommunicationPorts);
    }

    public PlcMemory Memory { get; }

    /// <summary>The program's blocks, OB1 first; CALL and ATCH name them by index.</summary>
    public StlBlock[] Blocks { get; }

    /// <summary>The field inputs; copied into I at the start of each scan, read directly by immediate contacts.</summary>
    public byte[] InputImage { get; }

    /// <summary>The outputs as the field sees them: Q copied at the end of each scan, written directly by immediate coils.</summary>
    public byte[] OutputImage { get; }

    public StlTime Time { get; } = new();

    public StlLogicStack Logic { get; } = new();

    public StlCallStack Calls { get; } = new();

    public StlTimers Timers { get; }

    public StlCounters Counters { get; } = new();

    public StlInterrupts Interrupts { get; }

    public StlEventSources Events { get; }

    public StlRealTimeClock Clock { get; }

    /// <summary>ENO of the last box instruction, for AENO: false when it had no power flow or met an error condition.</summary>
    public bool Eno { get; set; }

    /// <summary>The S bit of the running SCR segment (LSCR); null outside one.</summary>
    public StlLoc? ActiveScr { get; set; }

    /// <summary>The instruction running now, for the line of a fault.</summary>
    public StlOp? Op { get; set; }

    /// <summary>A fatal run-time error: the cycle puts the CPU in STOP after the instruction.</summary>
    public StlFault? Fault { get; set; }

    /// <summary>Set by STOP: the CPU finishes the scan, then goes to STOP (A5E00307987-04, "STOP" instruction).</summary>
    public StlFault? StopRequest { get; set; }

    /// <summary>Simulated time the scan watchdog counts from: the scan's start, or the last WDR.</summary>
    public long WatchdogFrom { get; set; }

    /// <summary>Raised when OB1 ends (its last instruction, END or MEND): the scan's housekeeping follows.</summary>
    public Action? MainEnded { get; set; }

    /// <summary>Raised when an interrupt routine returns.</summary>
    public Action? InterruptEnded { get; set; }

    public uint Accumulator(int number) => _ac[number];

    /// <summary>The bytes of I, Q, M, V, SM, S, AI or AQ; null for an area the CPU has no bytes of.</summary>
    public byte[]? Area(MemoryArea area) => _areas[(int)area];

    /// <summary>Time an instruction takes beyond its base time (per byte of a block move, per ASCII character).</summary>
    public void Charge(long nanoseconds) => _charge += nanoseconds;

    /// <summary>What <see cref="Charge"/> added since the last call.</summary>
    public long TakeCharge()
    {
        var charge = _charge;
        _charge = 0;
        return charge;
    }

    /// <summary>EU/ED: each instruction remembers the top of stack it saw last scan; the top becomes 1 only on the change.</summary>
    public void Edge(int slot, bool rising)
    {
        var now = Logic.Top;
        var fired = rising ? now && !_edges[slot] : !now && _edges[slot];
        _edges[slot] = now;
        Logic.SetTop(fired);
    }

    /// <summary>Records the first fatal error of the running instruction; always false, so a check can return it.</summary>
    public bool Fail(string code, string message)
    {
        if (Fault is null && Op is not null)
        {
            Fault = new StlFault(code, message, Calls.BlockName, Op.Line);
        }

        return false;
    }

    /// <summary>
    /// The CPU saves the accumulators and the instruction status bits (SMB1) around every interrupt routine, as it saves
    /// the logic stack (System Manual, "System Support for Interrupts", Table 6-47); interrupts never nest.
    /// </summary>
    public void SaveForInterrupt()
    {
        Array.Copy(_ac, _savedAc, _ac.Length);
        _savedFlags = Memory.SM[1];
    }

    public void RestoreAfterInterrupt()
    {
        Array.Copy(_savedAc, _ac, _ac.Length);
        Memory.SM[1] = _savedFlags;
    }
}
