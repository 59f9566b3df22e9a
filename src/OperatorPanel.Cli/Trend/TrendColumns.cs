using OperatorPanel.Historian.Reading;

namespace OperatorPanel.Cli.Trend;

/// <summary>
/// A trend cut into terminal columns: each column is an equal slice of the window and holds the lowest and highest value
/// the line had in it, or nothing (a gap: not recorded, stale or bad for the whole slice).
/// </summary>
internal static class TrendColumns
{
    public static (double Low, double High)?[] Of(TrendSeries series, int width)
    {
        ArgumentNullException.ThrowIfNull(series);
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        var columns = new (double Low, double High)?[width];
        var slice = (series.To - series.From) / width;
        foreach (var segment in series.Segments)
        {
            for (var p = 0; p + 1 < segment.Points.Count; p++)
            {
                var (from, to, value) = (segment.Points[p].At, segment.Points[p + 1].At, segment.Points[p].Value);
                var first = Math.Max(0, (int)((from - series.From) / slice));
                var last = Math.Min(width - 1, (int)Math.Ceiling((to - series.From) / slice) - 1);
                for (var c = first; c <= last; c++)
                {
                    columns[c] = columns[c] is { } had ? (Math.Min(had.Low, value), Math.Max(had.High, value)) : (value, value);
                }
            }
        }

        return columns;
    }
}
