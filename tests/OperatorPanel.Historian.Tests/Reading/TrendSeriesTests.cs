using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Reading;

namespace OperatorPanel.Historian.Tests.Reading;

/// <summary>Rows into a trend: held values as step segments, and gaps where the value was bad, stale or not recorded.</summary>
public sealed class TrendSeriesTests
{
    private static readonly DateTimeOffset T0 = new(2024, 1, 15, 8, 0, 0, TimeSpan.Zero);

    [Fact]
    public void Of_GoodRowsInOneSession_IsOneStepSegmentToTheWindowsEnd()
    {
        var series = TrendSeries.Of(History((0, 10, ValueQuality.Good), (60, 20, ValueQuality.Good)), [Span(0, 120)], T0, T0.AddSeconds(120));

        series.Gaps.Should().BeEmpty();
        series.Segments.Should().ContainSingle().Which.Points.Should().Equal(P(0, 10), P(60, 20), P(120, 20));
    }

    [Fact]
    public void Of_StaleAndBadRows_AreGapsOfTheirKind()
    {
        var series = TrendSeries.Of(
            History((0, 10, ValueQuality.Good), (30, 10, ValueQuality.Stale), (60, null, ValueQuality.Bad), (90, 30, ValueQuality.Good)),
            [Span(0, 120)], T0, T0.AddSeconds(120));

        series.Gaps.Should().Equal(new TrendGap(T0.AddSeconds(30), T0.AddSeconds(60), TrendGapKind.Stale), new TrendGap(T0.AddSeconds(60), T0.AddSeconds(90), TrendGapKind.Bad));
        series.Segments.Select(s => s.Points[0].Value).Should().Equal(10, 30);
    }

    [Fact]
    public void Of_RecorderStoppedBetweenSessions_IsANotRecordedGap()
    {
        var series = TrendSeries.Of(History((0, 10, ValueQuality.Good), (100, 11, ValueQuality.Good)), [Span(0, 40), Span(100, 120)], T0, T0.AddSeconds(120));

        series.Gaps.Should().Equal(new TrendGap(T0.AddSeconds(40), T0.AddSeconds(100), TrendGapKind.NotRecorded));
        series.Segments.Should().HaveCount(2);
    }

    [Fact]
    public void Of_WindowBeforeAnyRow_StartsWithANotRecordedGap()
    {
        var series = TrendSeries.Of(History((60, 10, ValueQuality.Good)), [Span(60, 120)], T0, T0.AddSeconds(120));

        series.Gaps.Should().Equal(new TrendGap(T0, T0.AddSeconds(60), TrendGapKind.NotRecorded));
    }

    [Fact]
    public void Of_LiveRecorder_HoldsTheLastValueUntilNow()
    {
        var series = TrendSeries.Of(History((0, 10, ValueQuality.Good)), [Span(0, 50)], T0, T0.AddSeconds(60), liveUntil: T0.AddSeconds(60));

        series.Gaps.Should().BeEmpty();
        series.Segments.Single().Points[^1].Should().Be(P(60, 10));
    }

    [Fact]
    public void At_Cursor_ReadsTheHeldValueOrTheGap()
    {
        var series = TrendSeries.Of(History((0, 10, ValueQuality.Good), (30, 10, ValueQuality.Stale), (60, 20, ValueQuality.Good)), [Span(0, 120)], T0, T0.AddSeconds(120));

        series.At(T0.AddSeconds(15)).Should().Be(new TrendReading(10, null));
        series.At(T0.AddSeconds(45)).Should().Be(new TrendReading(null, TrendGapKind.Stale));
        series.At(T0.AddSeconds(100)).Should().Be(new TrendReading(20, null));
    }

    private static TrendPoint P(int seconds, double value) => new(T0.AddSeconds(seconds), value);

    private static RecordingSpan Span(int from, int to) => new(T0.AddSeconds(from), T0.AddSeconds(to), "test");

    private static TagHistory History(params (int Seconds, long? Value, ValueQuality Quality)[] rows) =>
        new(new Station(2), PlcAddress.Parse("VW150"), "Level", DisplayFormat.Signed, [.. rows.Select(r => new HistorySample(T0.AddSeconds(r.Seconds), r.Value, r.Quality))]);
}
