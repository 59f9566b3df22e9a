namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// One completed interrupt routine run: which event, when it was raised, started and ended, and how many instructions it
/// executed (its subroutines included). <paramref name="InterruptedLine"/>: the .awl line of the main program's
/// instruction that runs next after the routine, 0 when the routine ran between OB1's end and the next scan (the user's
/// program time or the housekeeping).
/// </summary>
public sealed record StlInterruptRun(string Routine, int Event, TimeSpan RaisedAt, TimeSpan StartedAt, TimeSpan EndedAt, long Instructions, int InterruptedLine);
