namespace OperatorPanel.Historian.Reading;

/// <summary>What a history database holds: rows of each kind and its size on disk (file plus write-ahead log).</summary>
public sealed record HistoryFigures(long Samples, long Tags, long AlarmEvents, long AuditEntries, long Bytes);
