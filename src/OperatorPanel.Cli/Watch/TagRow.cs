namespace OperatorPanel.Cli.Watch;

/// <summary>One memory cell: symbol, address, value in its display format, quality.</summary>
internal sealed record TagRow(string Symbol, string Address, string Value, string Quality);
