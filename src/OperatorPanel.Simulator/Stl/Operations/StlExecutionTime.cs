namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>An instruction's execution time with power flow, in ns, and where the figure comes from (or why it was chosen).</summary>
internal sealed record StlExecutionTime(long Nanoseconds, string Source);
