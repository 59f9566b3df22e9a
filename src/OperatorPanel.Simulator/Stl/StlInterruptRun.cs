namespace OperatorPanel.Simulator.Stl;

/// <summary>One completed interrupt routine run: which event, when it was raised, started and ended, and how many instructions it executed (its subroutines included).</summary>
public sealed record StlInterruptRun(string Routine, int Event, TimeSpan RaisedAt, TimeSpan StartedAt, TimeSpan EndedAt, long Instructions);
