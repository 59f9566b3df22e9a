namespace OperatorPanel.Cli.Bench;

/// <summary>One simulated PPI refresh of the reference line: its time on the line, its characters, and its polls answered "not yet".</summary>
internal readonly record struct PpiRefresh(double Ms, long Chars, int EmptyPolls);
