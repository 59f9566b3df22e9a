namespace OperatorPanel.Cli.Bench;

/// <summary>One labelled part of an exchange's time, in ms.</summary>
internal readonly record struct TimePart(string What, double Ms);
