using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Recording;
using static OperatorPanel.Historian.Tests.HistoryFixture;

namespace OperatorPanel.Historian.Tests.Recording;

/// <summary>Retention by age and by size, run by the writer between batches.</summary>
public sealed class HistoryRetentionTests
{
    [Fact]
    public async Task Retention_RowsOlderThanTheRetentionDays_AreDeleted()
    {
        await using var history = new HistoryFixture(HistorySettings.Default with { RetentionDays = 1 });
        using var recording = history.Record();
        history.Time.Advance(TimeSpan.FromSeconds(1));
        history.Publish(Level, "0064");
        history.Time.Advance(TimeSpan.FromHours(20));
        history.Publish(Level, "00C8");
        await history.Historian.FlushAsync();

        history.Time.Advance(TimeSpan.FromHours(5)); // the first rows are now 25 h old
        await history.Historian.FlushAsync();

        var samples = await history.SamplesAsync(Level);
        // Retention runs at most once per Period, at whatever time the writer's loop reached while the clock moved: nothing
        // older than the retention days plus one period is left.
        samples[0].At.Should().BeOnOrAfter(history.Time.GetUtcNow().AddDays(-1) - HistoryRetention.Period);
        samples.Select(s => s.Stored).Should().Contain(100L, "the periodic samples of the last day stay").And.Contain(200L);
        history.Scalar("SELECT count(*) FROM samples WHERE value IS NULL").Should().Be(0, "the first row, 25 h old, is gone");
    }

    [Fact]
    public async Task Retention_DatabaseOverItsSize_DeletesTheOldestFirst()
    {
        // 1 MB: a limit below what a project file allows, so the test writes little.
        await using var history = new HistoryFixture(HistorySettings.Default with { MaxSizeMb = 1, DeadbandPercent = 0 });
        using var recording = history.Record();
        var start = history.Time.GetUtcNow();
        for (var i = 0; i < 80_000; i++)
        {
            history.Publish(Level, (i % 2 == 0 ? 0x1000 + i % 1000 : 0x3000).ToString("X4", System.Globalization.CultureInfo.InvariantCulture));
            history.Time.Advance(TimeSpan.FromMilliseconds(100));
            if (i % 10_000 == 0)
            {
                await history.Historian.FlushAsync();
            }
        }

        await history.Historian.FlushAsync();
        history.Time.Advance(TimeSpan.FromMinutes(10));
        await history.Historian.FlushAsync();

        var used = (history.Scalar("PRAGMA page_count") - history.Scalar("PRAGMA freelist_count")) * history.Scalar("PRAGMA page_size");
        used.Should().BeLessThanOrEqualTo(1024 * 1024);
        var oldest = (await history.SamplesAsync(Level))[0].At;
        oldest.Should().BeAfter(start.AddMinutes(30), "the oldest hours went first");
        (await history.SamplesAsync(Level))[^1].Stored.Should().Be(0x3000, "the newest rows stay");
    }
}
