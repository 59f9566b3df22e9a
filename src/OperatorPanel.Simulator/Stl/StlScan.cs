namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// One completed scan: from its start to the next scan's start, and the execution time in it (OB1 with its
/// subroutines, interrupt routines served meanwhile, and the housekeeping overhead).
/// </summary>
public sealed record StlScan(TimeSpan StartedAt, TimeSpan EndedAt, TimeSpan Busy);
