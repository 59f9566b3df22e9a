using OperatorPanel.Cli.Trend;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Reading;

namespace OperatorPanel.Cli.Tests.Trend;

/// <summary>A trend into terminal columns and block characters.</summary>
public sealed class TrendTextTests
{
    private static readonly DateTimeOffset T0 = new(2024, 1, 15, 8, 0, 0, TimeSpan.Zero);

    [Fact]
    public void Columns_RampWithAGap_EachColumnHoldsItsSlicesRangeAndTheGapIsEmpty()
    {
        var history = new TagHistory(new Station(2), PlcAddress.Parse("VW0"), "Level", DisplayFormat.Signed,
        [
            new HistorySample(T0, 0, ValueQuality.Good), new HistorySample(T0.AddSeconds(10), 10, ValueQuality.Good),
            new HistorySample(T0.AddSeconds(20), null, ValueQuality.Bad), new HistorySample(T0.AddSeconds(30), 30, ValueQuality.Good),
        ]);
        var series = TrendSeries.Of(history, [new RecordingSpan(T0, T0.AddSeconds(40), "test")], T0, T0.AddSeconds(40));

        var columns = TrendColumns.Of(series, 4);

        columns.Should().Equal((0d, 0d), (10d, 10d), null, (30d, 30d));
    }

    [Fact]
    public void Draw_LowestAndHighest_AreInTheBottomAndTopCellsAndAGapIsADot()
    {
        var rows = TrendText.Draw([(0d, 0d), null, (100d, 100d)], 2, out var min, out var max);

        (min, max).Should().Be((0, 100));
        rows.Should().Equal(["  █", "▁· "], "a value is drawn where it is, not filled from below");
    }

    [Fact]
    public void Draw_NoValueInTheWindow_HasNoRangeAndTheRangeLineSaysSo()
    {
        var rows = TrendText.Draw([null, null, null], 2, out var min, out var max);

        (min, max).Should().Be((null, null), "0 .. 0 would be a value nobody recorded");
        rows.Should().Equal(["   ", "···"]);
        TrendRenderer.Range(new TrendPanel("Filler.TankLevel", "-", "bad", min, max, rows, 1)).Should().Be("range none: no good value recorded in the window");
    }

    [Fact]
    public void Range_Values_GivesTheWindowsLowestAndHighestAndTheGaps()
    {
        TrendRenderer.Range(new TrendPanel("Filler.TankLevel", "55.2 %", "good", 12.5, 55.2, [], 2))
            .Should().Be("range 12.5 .. 55.2, 2 gap(s) (·: not recorded, stale or bad)");
    }
}
