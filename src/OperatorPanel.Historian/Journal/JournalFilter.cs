using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;

namespace OperatorPanel.Historian.Journal;

/// <summary>
/// A search of the alarm journal: every condition given must hold. <see cref="Text"/> matches anywhere in the alarm text
/// or the station's name, ignoring case (ASCII letters); the newest <see cref="Limit"/> matches are returned, oldest first.
/// </summary>
public sealed record JournalFilter(
    DateTimeOffset? From = null,
    DateTimeOffset? To = null,
    Station? Station = null,
    AlarmClass? Class = null,
    string? Text = null,
    int Limit = JournalFilter.DefaultLimit)
{
    public const int DefaultLimit = 5000;

    public static JournalFilter All { get; } = new();
}
