using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Simulator.Stl;

/// <summary>What a host (opanel stl run, tests) reads besides I, Q, M, V and SM: S, AI, AQ, timers and counters.</summary>
public sealed partial class StlPlc
{
    /// <summary>The bytes of I, Q, M, V, SM, S, AI or AQ (I is the process image the program reads).</summary>
    public byte[] AreaBytes(MemoryArea area)
    {
        if (area is MemoryArea.T or MemoryArea.C or MemoryArea.AC or MemoryArea.HC or MemoryArea.L || _areas[(int)area] is null)
        {
            throw new ArgumentOutOfRangeException(nameof(area), area, "timers, counters, accumulators, HC and L are not byte areas");
        }

        return _areas[(int)area];
    }

    /// <summary>Current value of Tn (0-32767), as the program would read it now.</summary>
    public short TimerCurrentValue(int timer) => TimerValue(timer);

    public bool TimerBitValue(int timer) => TimerBit(timer);

    public short CounterCurrentValue(int counter) => _counters[counter].Value;

    public bool CounterBitValue(int counter) => _counters[counter].Bit;
}
