namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>An interrupt event waiting in its priority group's queue, with the routine attached when it occurred.</summary>
internal readonly record struct StlQueuedEvent(int Event, int Block, long At);
