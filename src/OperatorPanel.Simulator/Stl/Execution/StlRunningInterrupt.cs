namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>The interrupt routine running now: its event, when it started (ns), the instruction count then, and the main program's next line.</summary>
internal readonly record struct StlRunningInterrupt(StlQueuedEvent Event, long StartedAt, long InstructionsBefore, int InterruptedLine);
