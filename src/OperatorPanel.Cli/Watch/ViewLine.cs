namespace OperatorPanel.Cli.Watch;

/// <summary>
/// One line of watch's view and how much it matters when the terminal is too low for all: <see cref="Keep"/> lines
/// (title, each station's state and error, its alarms) are always shown; higher numbers give way first.
/// </summary>
internal sealed record ViewLine(string Text, int Priority, ViewLineKind Kind = ViewLineKind.Plain)
{
    public const int Keep = 0;
    public const int Link = 1;
    public const int Tags = 2;
    public const int Lamps = 3;
    public const int LampSymbols = 4;
    public const int Spacing = 5;
}

/// <summary>What a line shows, for its colour on a terminal.</summary>
internal enum ViewLineKind
{
    Plain,
    Title,
    Station,
    Problem,
    Alarm,
    Unknown,
}
