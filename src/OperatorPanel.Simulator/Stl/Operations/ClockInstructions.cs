using OperatorPanel.Simulator.Stl.Execution;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>TODR T / TODW T: the 8 BCD bytes of the real-time clock (<see cref="StlRealTimeClock"/>); invalid data sets ENO = 0.</summary>
internal static class ClockInstructions
{
    public static void Read(StlMachine m, StlOp op)
    {
        if (m.TrySpan(op.A!, 8, out var area, out var offset))
        {
            m.Clock.Read(area.AsSpan(offset, 8));
        }
    }

    public static void Write(StlMachine m, StlOp op)
    {
        if (m.TrySpan(op.A!, 8, out var area, out var offset) && !m.Clock.TryWrite(area.AsSpan(offset, 8)))
        {
            m.Eno = false;
        }
    }
}
