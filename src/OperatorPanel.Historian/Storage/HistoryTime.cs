namespace OperatorPanel.Historian.Storage;

/// <summary>Times in the database: milliseconds since 1970-01-01 UTC (SQLite INTEGER; 6 bytes a row).</summary>
internal static class HistoryTime
{
    public static long ToMs(DateTimeOffset at) => at.ToUnixTimeMilliseconds();

    public static DateTimeOffset FromMs(long ms) => DateTimeOffset.FromUnixTimeMilliseconds(ms);
}
