using System.Diagnostics.CodeAnalysis;
using System.Globalization;

namespace OperatorPanel.Cli.History;

/// <summary>
/// The time range of <c>history</c>: <c>--since 90s|30m|2h|7d</c> back from now (default 1 h), or <c>--from</c> and
/// <c>--to</c> as ISO 8601 ("2024-01-15T08:00:00Z", "2024-01-15 08:00" in local time); --to defaults to now.
/// </summary>
internal static class TimeRange
{
    public static bool TryParse(string? since, string? from, string? to, TimeProvider time, out DateTimeOffset start, out DateTimeOffset end, [NotNullWhen(false)] out string? error)
    {
        var now = time.GetUtcNow();
        (start, end, error) = (now - TimeSpan.FromHours(1), now, null);
        if (since is not null && (from is not null || to is not null))
        {
            error = "give --since, or --from and --to, not both";
            return false;
        }

        if (since is not null)
        {
            if (!TryDuration(since, out var span))
            {
                error = $"--since '{since}': give a number and a unit, e.g. 90s, 30m, 2h or 7d";
                return false;
            }

            start = now - span;
            return true;
        }

        if (from is not null && !TryTime(from, time, out start))
        {
            error = $"--from '{from}': give a time as 2024-01-15T08:00:00Z or 2024-01-15 08:00 (local)";
            return false;
        }

        if (to is not null && !TryTime(to, time, out end))
        {
            error = $"--to '{to}': give a time as 2024-01-15T08:00:00Z or 2024-01-15 08:00 (local)";
            return false;
        }

        if (end < start)
        {
            error = "--to is before --from";
            return false;
        }

        return true;
    }

    public static bool TryDuration(string text, out TimeSpan span)
    {
        span = default;
        text = text.Trim();
        if (text.Length < 2 || !double.TryParse(text[..^1], NumberStyles.Float, CultureInfo.InvariantCulture, out var n) || !(n > 0) || n > 100_000)
        {
            return false;
        }

        TimeSpan? unit = char.ToLowerInvariant(text[^1]) switch
        {
            's' => TimeSpan.FromSeconds(n),
            'm' => TimeSpan.FromMinutes(n),
            'h' => TimeSpan.FromHours(n),
            'd' => TimeSpan.FromDays(n),
            _ => null,
        };
        span = unit ?? default;
        return unit is not null;
    }

    private static bool TryTime(string text, TimeProvider time, out DateTimeOffset at)
    {
        string[] local = ["yyyy-MM-dd HH:mm", "yyyy-MM-dd HH:mm:ss", "yyyy-MM-dd'T'HH:mm", "yyyy-MM-dd'T'HH:mm:ss", "yyyy-MM-dd"];
        if (text.EndsWith('Z') || text.Contains('+', StringComparison.Ordinal) || (text.Length > 19 && text[19..].Contains('-', StringComparison.Ordinal)))
        {
            return DateTimeOffset.TryParse(text, CultureInfo.InvariantCulture, DateTimeStyles.AdjustToUniversal, out at);
        }

        if (DateTime.TryParseExact(text, local, CultureInfo.InvariantCulture, DateTimeStyles.None, out var plain))
        {
            at = new DateTimeOffset(plain, time.LocalTimeZone.GetUtcOffset(plain));
            return true;
        }

        at = default;
        return false;
    }
}
