namespace OperatorPanel.ViewModels.Alarms;

/// <summary>The time ranges the alarm journal offers, back from now; <see cref="Custom"/> takes From and To.</summary>
public enum JournalRange
{
    LastHour,
    Shift,
    Day,
    Week,
    All,
    Custom,
}
