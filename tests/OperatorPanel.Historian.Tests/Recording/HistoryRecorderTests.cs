using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Reading;
using static OperatorPanel.Historian.Tests.HistoryFixture;

namespace OperatorPanel.Historian.Tests.Recording;

/// <summary>What of the line's values becomes a row: deadbands, quality, periodic samples, what is not recorded.</summary>
public sealed class HistoryRecorderTests
{
    [Fact]
    public async Task Record_Subscribing_RecordsEveryValueOnceAsNotReadYet()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();

        var samples = await history.SamplesAsync(Level);

        samples.Should().ContainSingle().Which.Should().Be(new HistorySample(history.Time.GetUtcNow(), null, ValueQuality.Bad));
    }

    [Fact]
    public async Task Record_NumberWithinTheProjectDeadband_IsNotRecordedBeyondItIs()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();
        history.Publish(Level, "03E8"); // 1000
        history.Time.Advance(TimeSpan.FromSeconds(1));
        history.Publish(Level, "03EC"); // 1004: 0.4 % of 1000, inside 0.5 %
        history.Time.Advance(TimeSpan.FromSeconds(1));
        history.Publish(Level, "03EE"); // 1006: 0.6 % of 1000

        var values = (await history.SamplesAsync(Level)).Select(s => s.Stored);

        values.Should().Equal(null, 1000, 1006);
    }

    [Fact]
    public async Task Record_TagDeadband_IsInTheTagsUnits()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();
        history.Publish(Setpoint, Float(10f));
        history.Publish(Setpoint, Float(10.2f)); // 0.2 <= 0.25
        history.Publish(Setpoint, Float(10.3f)); // 0.3 > 0.25

        var values = (await history.SamplesAsync(Setpoint)).Where(s => s.Stored is not null).Select(s => BitConverter.UInt32BitsToSingle((uint)s.Stored!.Value));

        values.Should().Equal(10f, 10.3f);
    }

    [Fact]
    public async Task Record_CodeOrBit_RecordsEveryChange()
    {
        await using var history = new HistoryFixture(HistorySettings.Default with { DeadbandPercent = 100 });
        using var recording = history.Record();
        history.Publish(Fault, "10");
        history.Publish(Fault, "11");
        history.Publish(Input, "01");
        history.Publish(Input, "00");

        (await history.SamplesAsync(Fault)).Select(s => s.Stored).Should().Equal(null, 0x10, 0x11);
        (await history.SamplesAsync(Input)).Select(s => s.Stored).Should().Equal(null, 1, 0);
    }

    [Fact]
    public async Task Record_GoodThenStale_KeepsTheGoodRowAndStampsTheStaleOneNow()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();
        history.Time.Advance(TimeSpan.FromSeconds(1));
        history.Publish(Level, "0064");
        var goodAt = history.Time.GetUtcNow();
        history.Time.Advance(TimeSpan.FromSeconds(3));
        // The line keeps a stale value's last good read time; the row must not replace the good one.
        history.Line.Publish([new ValueChange(Station, Level, null!, new PolledValue([0x00, 0x64], goodAt, ValueQuality.Stale, "no answer"))]);

        var samples = await history.SamplesAsync(Level);

        samples.Skip(1).Should().Equal(
            new HistorySample(goodAt, 100, ValueQuality.Good),
            new HistorySample(goodAt.AddSeconds(3), 100, ValueQuality.Stale));
    }

    [Fact]
    public async Task Record_FlatValue_IsSampledOncePerSamplePeriod()
    {
        await using var history = new HistoryFixture(HistorySettings.Default with { SamplePeriod = TimeSpan.FromMinutes(10) });
        using var recording = history.Record();
        history.Time.Advance(TimeSpan.FromSeconds(1));
        history.Publish(Level, "0064");
        var start = history.Time.GetUtcNow();

        history.Time.Advance(TimeSpan.FromMinutes(30));

        var times = (await history.SamplesAsync(Level)).Skip(1).Select(s => s.At).ToList();
        times.Should().HaveCount(4).And.StartWith(start);
        times.Zip(times.Skip(1), (a, b) => b - a).Should().OnlyContain(gap => gap <= TimeSpan.FromMinutes(10));
    }

    [Fact]
    public async Task Record_TagMarkedNotRecorded_HasNoRows()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();
        history.Publish(Counter, "00000005");

        (await history.SamplesAsync(Counter)).Should().BeEmpty();
        history.Scalar("SELECT count(*) FROM tags WHERE address = 'VD100'").Should().Be(0);
    }

    [Fact]
    public async Task Record_HistoryTurnedOff_RecordsNoValues()
    {
        await using var history = new HistoryFixture(HistorySettings.Default with { Enabled = false });
        using var recording = history.Record();
        history.Publish(Level, "0064");

        (await history.SamplesAsync(Level)).Should().BeEmpty();
    }

    [Fact]
    public async Task Record_StationState_IsRecordedWhenItChanges()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();
        history.Statuses[Station] = StationStatus.Initial(Station) with { State = StationState.Online };
        history.Time.Advance(TimeSpan.FromSeconds(3));
        history.Statuses[Station] = StationStatus.Initial(Station) with { State = StationState.Offline, LastError = "no answer" };
        history.Time.Advance(TimeSpan.FromSeconds(1));
        await history.Historian.FlushAsync();

        history.Scalar("SELECT count(*) FROM station_states").Should().Be(3);
        history.Scalar("SELECT count(*) FROM station_states WHERE state = 'offline' AND error = 'no answer'").Should().Be(1);
    }

    private static string Float(float value) => BitConverter.SingleToUInt32Bits(value).ToString("X8", System.Globalization.CultureInfo.InvariantCulture);
}
