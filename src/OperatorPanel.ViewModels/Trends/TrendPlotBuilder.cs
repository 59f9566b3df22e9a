using OperatorPanel.Historian.Reading;

namespace OperatorPanel.ViewModels.Trends;

/// <summary>
/// Turns the history of the picked tags over a window into a <see cref="TrendPlot"/>: a <see cref="TrendSeries"/> per tag
/// (held values, gaps), thinned to at most <see cref="MaxPointsPerLane"/> points per lane, keeping each slice's first,
/// lowest, highest and last point so no peak is lost: a day of 100 ms changes draws as fast as a minute.
/// </summary>
public static class TrendPlotBuilder
{
    public const int MaxPointsPerLane = 4000;

    public static TrendPlot Build(
        IReadOnlyList<TrendTagViewModel> tags, IReadOnlyList<TagHistory> histories, IReadOnlyList<RecordingSpan> spans,
        DateTimeOffset from, DateTimeOffset to, DateTimeOffset? liveUntil, DateTimeOffset? cursor)
    {
        ArgumentNullException.ThrowIfNull(tags);
        ArgumentNullException.ThrowIfNull(histories);
        var lanes = tags.Zip(histories, (tag, history) =>
        {
            var series = TrendSeries.Of(history, spans, from, to, liveUntil);
            var segments = Thin(series.Segments, from, to);
            var values = segments.SelectMany(s => s.Points).Select(p => p.Value).ToList();
            var (min, max) = values.Count > 0 ? (values.Min(), values.Max()) : (0, 1);
            return new TrendLane(tag.Name, tag.Color, segments, series.Gaps, min, max, tag.IsBit);
        });
        return new TrendPlot(from, to, [.. lanes], cursor, liveUntil is not null);
    }

    private static List<TrendSegment> Thin(IReadOnlyList<TrendSegment> segments, DateTimeOffset from, DateTimeOffset to)
    {
        var total = segments.Sum(s => s.Points.Count);
        if (total <= MaxPointsPerLane)
        {
            return [.. segments];
        }

        var slice = (to - from) / (MaxPointsPerLane / 4);
        return [.. segments.Select(s => new TrendSegment(Thin(s.Points, from, slice)))];
    }

    private static List<TrendPoint> Thin(IReadOnlyList<TrendPoint> points, DateTimeOffset from, TimeSpan slice)
    {
        var kept = new List<TrendPoint>();
        foreach (var bucket in points.GroupBy(p => (long)((p.At - from) / slice)))
        {
            var inSlice = bucket.ToList();
            var chosen = new[] { inSlice[0], inSlice.MinBy(p => p.Value), inSlice.MaxBy(p => p.Value), inSlice[^1] };
            kept.AddRange(chosen.Distinct().OrderBy(p => p.At));
        }

        // The segment's end stays, so a held value reaches the right edge.
        if (kept[^1] != points[^1])
        {
            kept.Add(points[^1]);
        }

        return kept;
    }
}
