using OperatorPanel.Simulator.Stl.Execution;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// TON, TONR, TOF (<see cref="StlTimers"/>) and CTU, CTD, CTUD (<see cref="StlCounters"/>): the top of the logic stack
/// (and for counters the levels below it) are the box's inputs; op.A is the timer or counter, op.B its preset.
/// </summary>
internal static class TimerCounterInstructions
{
    public static void Timer(StlMachine m, StlOp op) =>
        m.Timers.Execute(op.A!.Offset, op.Code, (short)m.Read(op.B!, 2), m.Logic.Top);

    public static void Counter(StlMachine m, StlOp op) =>
        m.Counters.Execute(op.A!.Offset, op.Code, (short)m.Read(op.B!, 2), m.Logic);
}
