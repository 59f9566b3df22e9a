using System.Collections.Immutable;

namespace OperatorPanel.Core.Alarms;

/// <summary>What loading the alarm history gave: the entries (oldest first), and a message for the operator when the file
/// needed attention (a torn last line dropped, or a corrupt file set aside).</summary>
public sealed record AlarmHistoryLoad(ImmutableArray<AlarmEvent> Events, string? Message);
