namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>A character a port put on the line, as the PC side collects it.</summary>
/// <param name="Value">The character (0 for a break).</param>
/// <param name="At">Simulated time at which its stop bit ended (for a break, the end of the 16 bit times).</param>
/// <param name="IsBreak">XMT with count 0: the line held low for 16 bit times (facts section 8).</param>
/// <param name="IsPpi">Sent by the CPU's PPI side (a PPI telegram), not by the program's XMT.</param>
public readonly record struct WireCharacter(byte Value, TimeSpan At, bool IsBreak = false, bool IsPpi = false);
