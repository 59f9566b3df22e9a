namespace OperatorPanel.Historian.Reading;

/// <summary>A time the recorder ran (a session from its start to its last stored batch): outside these, nothing is known.</summary>
public readonly record struct RecordingSpan(DateTimeOffset From, DateTimeOffset To, string Source);
