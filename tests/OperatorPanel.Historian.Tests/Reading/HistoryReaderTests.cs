using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;
using OperatorPanel.Historian.Reading;
using OperatorPanel.Historian.Recording;
using static OperatorPanel.Historian.Tests.HistoryFixture;

namespace OperatorPanel.Historian.Tests.Reading;

/// <summary>Reading ranges: the row before the range, the recording sessions, a database not made yet.</summary>
public sealed class HistoryReaderTests
{
    [Fact]
    public async Task Read_Range_StartsWithTheValueHeldAtItsStart()
    {
        await using var history = new HistoryFixture(HistorySettings.Default with { DeadbandPercent = 0 });
        using var recording = history.Record();
        var start = history.Time.GetUtcNow();
        foreach (var raw in new[] { "0001", "0002", "0003" })
        {
            history.Time.Advance(TimeSpan.FromMinutes(1));
            history.Publish(Level, raw);
        }

        await history.Historian.FlushAsync();
        var range = history.Historian.Reader.Read([(Station, Level)], start.AddMinutes(2.5), start.AddMinutes(10))[0];

        range.Symbol.Should().Be("Level");
        range.Format.Should().Be(DisplayFormat.Signed);
        range.Samples.Select(s => s.Stored).Should().Equal(2, 3);
        range.Samples[0].At.Should().Be(start.AddMinutes(2));
    }

    [Fact]
    public async Task Read_ScaledTagWithUnit_GivesEngineeringNumbersAndTexts()
    {
        await using var history = new HistoryFixture(HistorySettings.Default with { DeadbandPercent = 0 });
        using var recording = history.Record();
        var start = history.Time.GetUtcNow();
        history.Time.Advance(TimeSpan.FromMinutes(1));
        history.Publish(Level, "00A7");
        await history.Historian.FlushAsync();
        var level = RecordedTag.Of(history.Project).Single(t => t.Address == Level) with
        {
            Scale = new TagScale(0, 1000, 0, 100),
            Unit = "%",
        };

        var range = history.Historian.Reader.Read([level], start, start.AddMinutes(10))[0];
        var last = range.Samples[^1];

        last.Stored.Should().Be(167, "the raw word stays raw in the database");
        range.Number(last).Should().BeApproximately(16.7, 1e-9, "TankLevel's 0..1000 -> 0..100 %");
        range.Text(last).Should().Be("16.7 %");
        level.Text([0x00, 0xA7]).Should().Be("16.7 %");
    }

    [Fact]
    public async Task Sessions_RecorderRan_IsOneSpanUpToTheLastBatch()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();
        var start = history.Time.GetUtcNow();
        await history.Historian.FlushAsync();
        history.Time.Advance(TimeSpan.FromMinutes(5));
        await history.Historian.FlushAsync();

        var spans = history.Historian.Reader.Sessions(start.AddHours(-1), start.AddHours(1));

        spans.Should().ContainSingle().Which.Should().Be(new RecordingSpan(start, start.AddMinutes(5), "test"));
    }

    [Fact]
    public async Task Sessions_FlushLessThanAMinuteAfterTheLastMark_EndsTheSpanAtTheFlush()
    {
        // The writer's loop may wake on its own during a clock jump and mark the session then (08:04:17 here); a flush
        // 43 s later must still move the end to its own time, though the idle mark (once a minute) is not due.
        await using var history = new HistoryFixture();
        using var recording = history.Record();
        var start = history.Time.GetUtcNow();
        history.Time.Advance(TimeSpan.FromSeconds(257));
        await history.Historian.FlushAsync();
        history.Time.Advance(TimeSpan.FromSeconds(43));
        await history.Historian.FlushAsync();

        var spans = history.Historian.Reader.Sessions(start.AddHours(-1), start.AddHours(1));

        spans.Should().ContainSingle().Which.To.Should().Be(start.AddMinutes(5));
    }

    [Fact]
    public async Task Audit_WriteAndStop_ReadBackAsRecorded()
    {
        await using var history = new HistoryFixture();
        var at = history.Time.GetUtcNow();
        var write = new AuditEntry(Guid.NewGuid(), AuditStep.Intent, AuditAction.Write, at, "PLANT\\maria", "COM3", Station, "VW10", "Speed", "16#0000", "16#002A");
        var stop = new AuditEntry(Guid.NewGuid(), AuditStep.Intent, AuditAction.Stop, at.AddSeconds(2), "PLANT\\maria", "COM3", Station, null, null, "RUN", "STOP");
        AuditEntry[] entries = [write, write.Then(AuditStep.Outcome, at.AddSeconds(1), "read back differently", "read back 16#0029"), stop, stop.Then(AuditStep.Outcome, at.AddSeconds(3), "stopped", null)];
        foreach (var entry in entries)
        {
            (await history.Historian.Audit.RecordAsync(entry, CancellationToken.None)).Should().BeNull();
        }

        await history.Historian.FlushAsync();

        history.Historian.Reader.Audit(at.AddMinutes(-1), at.AddMinutes(1)).Should().Equal(entries);
    }

    [Fact]
    public void Read_NoDatabaseYet_IsEmpty()
    {
        var reader = new HistoryReader(Path.Combine(Path.GetTempPath(), "opanel-none-" + Guid.NewGuid().ToString("N") + ".history.db"));

        reader.Read([(Station, Level)], DateTimeOffset.UnixEpoch, DateTimeOffset.MaxValue.AddDays(-1)).Should().BeEmpty();
        reader.Figures().Samples.Should().Be(0);
    }

    [Fact]
    public async Task Read_ValueNeverRecorded_HasNoRows()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();
        await history.Historian.FlushAsync();

        history.Historian.Reader.Read([(Station, Core.Addressing.PlcAddress.Parse("VW999"))], DateTimeOffset.UnixEpoch, history.Time.GetUtcNow()).Single().Samples.Should().BeEmpty();
    }
}
