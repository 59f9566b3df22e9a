using OperatorPanel.Core.Alarms;

namespace OperatorPanel.Historian.Journal;

/// <summary>One line of the alarm journal: the transition as it was recorded (its text and class at that time) and who acknowledged it.</summary>
/// <param name="Id">Order of recording; later entries have larger ids.</param>
/// <param name="Event">Time, station, flag, transition, state after it, class and text.</param>
/// <param name="User">Who acknowledged (for an acknowledgement); null otherwise and for imported entries.</param>
public sealed record JournalEntry(long Id, AlarmEvent Event, string? User);
