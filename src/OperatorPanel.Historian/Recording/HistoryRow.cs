using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Historian.Recording;

/// <summary>One thing queued for the database; the writer stores a batch of them in one transaction.</summary>
internal abstract record HistoryRow;

/// <summary>A tag's value: its bytes as one unsigned integer (null when there is none), with its quality.</summary>
internal sealed record SampleRow(RecordedTag Tag, DateTimeOffset At, long? Value, ValueQuality Quality) : HistoryRow;

/// <summary>A station went online, offline, stopped by the panel, or back to unknown (disconnected).</summary>
internal sealed record StationStateRow(Station Station, DateTimeOffset At, StationState State, string? Error) : HistoryRow;

/// <summary>An alarm was raised, cleared or acknowledged; <paramref name="User"/> acknowledged it.</summary>
internal sealed record AlarmRow(AlarmEvent Event, string? User) : HistoryRow;

internal sealed record AuditRow(AuditEntry Entry) : HistoryRow;

/// <summary>A fact about the database itself (a history file imported once).</summary>
internal sealed record MetaRow(string Key, string Value) : HistoryRow;

/// <summary>Not stored: completes when every row queued before it has been written (or its write has failed).</summary>
internal sealed record FlushMarker(TaskCompletionSource Done) : HistoryRow;
