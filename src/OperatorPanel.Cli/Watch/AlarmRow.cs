namespace OperatorPanel.Cli.Watch;

/// <summary>An alarm the operator must see: its flag is set ("active"), or its flag has no good reading ("unknown").</summary>
internal sealed record AlarmRow(string Flag, string Text, string Class, string State)
{
    public const string Active = "active";
    public const string Unknown = "unknown";
}
