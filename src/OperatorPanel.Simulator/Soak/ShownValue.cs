namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// VD<paramref name="Offset"/> shown as good with <paramref name="Value"/>: it must be a value the PLC held there at
/// some moment from <paramref name="From"/> (the start of the step before, which may have set it by a write's
/// read-back) to <paramref name="Until"/> (when it was shown), both TimeProvider ticks.
/// </summary>
public readonly record struct ShownValue(int Offset, uint Value, long From, long Until);
