namespace OperatorPanel.Cli.Watch;

/// <summary>An alarm whose flag bit is set.</summary>
internal sealed record AlarmRow(string Flag, string Text, string Class);
