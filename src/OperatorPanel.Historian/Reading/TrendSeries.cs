using OperatorPanel.Core.Polling;

namespace OperatorPanel.Historian.Reading;

/// <summary>
/// A value's history over a window as a trend draws it: stretches where it was known (each row held until the next, a
/// step line) and gaps where it was not: bad or stale rows, and the times the recorder did not run. The panel's Trends
/// window and <c>opanel trend</c> both draw from this.
/// </summary>
public sealed record TrendSeries(DateTimeOffset From, DateTimeOffset To, IReadOnlyList<TrendSegment> Segments, IReadOnlyList<TrendGap> Gaps)
{
    /// <param name="history">The value's rows (the row before <paramref name="from"/> included, as HistoryReader reads them).</param>
    /// <param name="spans">When the recorder ran.</param>
    /// <param name="from">The window's start.</param>
    /// <param name="to">The window's end.</param>
    /// <param name="liveUntil">The recorder runs now: the latest span reaches this time (its stored end lags by up to a batch).</param>
    public static TrendSeries Of(TagHistory history, IReadOnlyList<RecordingSpan> spans, DateTimeOffset from, DateTimeOffset to, DateTimeOffset? liveUntil = null)
    {
        ArgumentNullException.ThrowIfNull(history);
        ArgumentNullException.ThrowIfNull(spans);
        var covered = Covered(spans, liveUntil);
        var segments = new List<TrendSegment>();
        var gaps = new List<TrendGap>();
        var samples = history.Samples;
        for (var i = 0; i < samples.Count; i++)
        {
            var sample = samples[i];
            var next = i + 1 < samples.Count ? samples[i + 1].At : to;
            var start = Max(sample.At, from);
            var end = Min(next, to);
            if (end <= start)
            {
                continue;
            }

            foreach (var (a, b, recorded) in Split(start, end, covered))
            {
                if (!recorded)
                {
                    gaps.Add(new TrendGap(a, b, TrendGapKind.NotRecorded));
                }
                else if (sample.Quality != ValueQuality.Good || history.Number(sample) is not { } value)
                {
                    gaps.Add(new TrendGap(a, b, sample.Quality == ValueQuality.Stale ? TrendGapKind.Stale : TrendGapKind.Bad));
                }
                else
                {
                    Extend(segments, a, b, value);
                }
            }
        }

        var first = samples.Count > 0 ? Max(samples[0].At, from) : to;
        if (first > from)
        {
            gaps.Insert(0, new TrendGap(from, first, TrendGapKind.NotRecorded));
        }

        return new TrendSeries(from, to, segments, Merge(gaps));
    }

    /// <summary>The value and quality in effect at <paramref name="at"/> (a cursor's reading); null where nothing is known.</summary>
    public TrendReading? At(DateTimeOffset at)
    {
        if (Gaps.FirstOrDefault(g => g.From <= at && at < g.To) is { } gap)
        {
            return new TrendReading(null, gap.Kind);
        }

        foreach (var segment in Segments)
        {
            for (var i = segment.Points.Count - 1; i >= 0; i--)
            {
                if (segment.Points[i].At <= at && at <= segment.Points[^1].At)
                {
                    return new TrendReading(segment.Points[i].Value, null);
                }
            }
        }

        return null;
    }

    /// <summary>Adds a held value from <paramref name="a"/> to <paramref name="b"/>, continuing the last segment when it ends at <paramref name="a"/>.</summary>
    private static void Extend(List<TrendSegment> segments, DateTimeOffset a, DateTimeOffset b, double value)
    {
        if (segments.Count > 0 && segments[^1].Points[^1].At == a)
        {
            var points = (List<TrendPoint>)segments[^1].Points;
            points[^1] = new TrendPoint(a, value);
            points.Add(new TrendPoint(b, value));
            return;
        }

        segments.Add(new TrendSegment(new List<TrendPoint> { new(a, value), new(b, value) }));
    }

    /// <summary>The spans, merged where they touch, the latest one stretched to <paramref name="liveUntil"/>.</summary>
    private static List<(DateTimeOffset From, DateTimeOffset To)> Covered(IReadOnlyList<RecordingSpan> spans, DateTimeOffset? liveUntil)
    {
        var ordered = spans.OrderBy(s => s.From).Select(s => (s.From, s.To)).ToList();
        if (liveUntil is { } live && ordered.Count > 0 && live > ordered[^1].To)
        {
            ordered[^1] = (ordered[^1].From, live);
        }

        return ordered;
    }

    /// <summary>[a, b) cut at the spans' edges, each piece marked recorded or not.</summary>
    private static IEnumerable<(DateTimeOffset, DateTimeOffset, bool)> Split(DateTimeOffset a, DateTimeOffset b, List<(DateTimeOffset From, DateTimeOffset To)> covered)
    {
        var at = a;
        foreach (var (from, to) in covered)
        {
            if (to <= at || from >= b)
            {
                continue;
            }

            if (from > at)
            {
                yield return (at, from, false);
                at = from;
            }

            var end = Min(to, b);
            yield return (at, end, true);
            at = end;
        }

        if (at < b)
        {
            yield return (at, b, false);
        }
    }

    private static List<TrendGap> Merge(List<TrendGap> gaps)
    {
        var merged = new List<TrendGap>();
        foreach (var gap in gaps.OrderBy(g => g.From))
        {
            if (merged.Count > 0 && merged[^1].To == gap.From && merged[^1].Kind == gap.Kind)
            {
                merged[^1] = merged[^1] with { To = gap.To };
            }
            else
            {
                merged.Add(gap);
            }
        }

        return merged;
    }

    private static DateTimeOffset Max(DateTimeOffset a, DateTimeOffset b) => a > b ? a : b;

    private static DateTimeOffset Min(DateTimeOffset a, DateTimeOffset b) => a < b ? a : b;
}
