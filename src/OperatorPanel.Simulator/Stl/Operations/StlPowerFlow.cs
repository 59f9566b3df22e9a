namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>Whether an instruction runs when the top of the logic stack is 0.</summary>
internal enum StlPowerFlow
{
    /// <summary>Contacts, coils, the logic stack, compares, timers, counters, returns: run whatever the top holds.</summary>
    Any,

    /// <summary>
    /// Box instructions: run only with power flow (top of stack 1) and leave the stack unchanged; without it ENO = 0 and
    /// they take <see cref="StlTiming.WithoutPowerFlow"/> unless their row says otherwise.
    /// </summary>
    Required,
}
