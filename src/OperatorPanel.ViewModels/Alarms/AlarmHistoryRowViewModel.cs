using OperatorPanel.Core.Alarms;
using OperatorPanel.Historian.Journal;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// One entry of the alarm journal in the Alarms window's History tab, at the TimeProvider's local time like the alarm
/// table beside it; the CSV export, the print page's source and the database keep <see cref="Event"/>'s UTC time.
/// </summary>
public sealed class AlarmHistoryRowViewModel
{
    internal AlarmHistoryRowViewModel(JournalEntry entry, TimeZoneInfo zone)
    {
        Entry = entry;
        At = TimeZoneInfo.ConvertTime(entry.Event.At, zone);
    }

    /// <summary>The journal's entry as recorded.</summary>
    public JournalEntry Entry { get; }

    public AlarmEvent Event => Entry.Event;

    /// <summary>When it happened, local time.</summary>
    public DateTimeOffset At { get; }

    public AlarmTransition Transition => Event.Transition;

    public string TransitionText => Event.TransitionText;

    public string StationName => Event.StationName;

    public string Flag => Event.Flag.ToString();

    public string Text => Event.Text;

    public string StateText => Event.StateText;

    /// <summary>Who acknowledged; empty for a raise, a clear or an imported entry.</summary>
    public string User => Entry.User ?? string.Empty;
}
