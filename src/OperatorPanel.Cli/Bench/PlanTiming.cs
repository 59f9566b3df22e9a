namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The planner timed on one tag count: the median of <paramref name="Runs"/> runs after a warm-up, the slowest, the
/// bytes the median run allocated, and what the plan came to (frames, items accepted, characters per cycle).
/// </summary>
internal sealed record PlanTiming(int Tags, int Runs, double MedianMs, double MaxMs, long AllocatedBytes, int Frames, int Values, int Rejected);
