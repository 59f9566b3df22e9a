namespace OperatorPanel.Simulator.Stl;

/// <summary>An interrupt event (9/26 transmit complete, 23/24 receive message complete, 10/11 timed interrupts 0/1; docs/sources/s7200-facts.md section 5) and when it occurred.</summary>
/// <param name="Number">The event number ATCH names.</param>
/// <param name="At">Simulated time since power-up.</param>
public readonly record struct StlEvent(int Number, TimeSpan At);
