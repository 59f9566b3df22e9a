using System.Globalization;

namespace OperatorPanel.Core.Alarms;

/// <summary>Alarm times as files write them: ISO 8601 in UTC with milliseconds, "2024-01-15T08:00:00.250Z".</summary>
public static class AlarmTime
{
    private const string Pattern = "yyyy-MM-dd'T'HH:mm:ss.fff'Z'";

    public static string Format(DateTimeOffset at) => at.UtcDateTime.ToString(Pattern, CultureInfo.InvariantCulture);

    public static bool TryParse(string? text, out DateTimeOffset at) =>
        DateTimeOffset.TryParseExact(text, Pattern, CultureInfo.InvariantCulture, DateTimeStyles.AssumeUniversal | DateTimeStyles.AdjustToUniversal, out at);
}
