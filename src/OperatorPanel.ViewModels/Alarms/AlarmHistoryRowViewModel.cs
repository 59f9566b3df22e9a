using OperatorPanel.Core.Alarms;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// One transition in the alarm window's history, at the TimeProvider's local time like the alarm table beside it; the
/// CSV export and the history file keep <see cref="Event"/>'s UTC time.
/// </summary>
public sealed class AlarmHistoryRowViewModel
{
    internal AlarmHistoryRowViewModel(AlarmEvent entry, TimeZoneInfo zone)
    {
        Event = entry;
        At = TimeZoneInfo.ConvertTime(entry.At, zone);
    }

    public AlarmEvent Event { get; }

    /// <summary>When it happened, local time.</summary>
    public DateTimeOffset At { get; }

    public AlarmTransition Transition => Event.Transition;

    public string TransitionText => Event.TransitionText;

    public string StationName => Event.StationName;

    public string Flag => Event.Flag.ToString();

    public string Text => Event.Text;

    public string StateText => Event.StateText;
}
