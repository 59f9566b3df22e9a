namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Why the simulated CPU went to STOP on its own: a fatal run-time error with a short code the host can show
/// (IndirectAddress, OperandRange, NestingDepth, Watchdog, PortBuffer), and the block and line of the instruction.
/// </summary>
public sealed record StlFault(string Code, string Message, string Block, int Line)
{
    public override string ToString() => $"{Code} in {Block} line {Line}: {Message}";
}
