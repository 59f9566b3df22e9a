using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.TestKit;
using OperatorPanel.ViewModels.Alarms;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Tests.Fakes;
using static OperatorPanel.ViewModels.Tests.Fakes.AlarmProject;

namespace OperatorPanel.ViewModels.Tests.Alarms;

/// <summary>Alarms of a station not read are unknown, never all clear: in the table, the banner's line and both summaries.</summary>
public sealed class AlarmsUnknownTests
{
    private readonly ManualTimeProvider _clock = new();
    private readonly FakeLineValues _values = new();
    private readonly ScriptedFileDialogs _files = new();

    [Fact]
    public void Alarms_StationNotRead_ShowUnknownInTheTableBannerAndSummaryNotAllClear()
    {
        var filler = new StationStatusViewModel(AlarmProject.Create().Stations[0]);
        using var alarms = new AlarmsViewModel(AlarmProject.Create(), null, _values, _clock, new AlarmServices(_files, SilentAlarmSound.Instance, null, Path.GetTempPath(), "maria"), [filler]);
        alarms.StartAsync().IsCompletedSuccessfully.Should().BeTrue("without a journal the window starts at once");
        filler.Update(new StationStatus(AlarmProject.Station, StationState.Offline, "PortUnavailable: serial port COM3: open failed", 1, null), LinkStatistics.Empty);

        alarms.UnknownText.Should().Be("alarms unknown: Filler offline");
        alarms.Summary.Should().Be("alarms unknown");
        alarms.BannerText.Should().Be("alarms unknown: Filler offline");
        Row(alarms, Jam).IsKnown.Should().BeFalse();
        Row(alarms, Jam).StateText.Should().Be("unknown");

        _values.Publish([.. Bit(Jam, on: true), .. Bit(LowLevel, on: false), .. Bit(DoorOpen, on: false)]);
        filler.Update(new StationStatus(AlarmProject.Station, StationState.Online, null, 0, _clock.GetUtcNow()), LinkStatistics.Empty);
        alarms.UnknownText.Should().BeNull();
        alarms.Summary.Should().Be("1 alarm active, 1 unacknowledged");
        alarms.BannerText.Should().Be("1 active, 1 unacknowledged");

        _values.Publish(Bit(Jam, on: true, ValueQuality.Stale));
        filler.Update(new StationStatus(AlarmProject.Station, StationState.Offline, "NoAnswer: no answer", 3, _clock.GetUtcNow()), LinkStatistics.Empty);
        Row(alarms, Jam).StateText.Should().Be("unknown (was active unacknowledged)");
        Row(alarms, Jam).IsPending.Should().BeTrue("the operator still owes the acknowledgement");
        alarms.UnknownText.Should().Be("alarms unknown: Filler not answering", "it answered before: STOP, TERM or off the bus");
        alarms.Summary.Should().Be("alarms unknown; when last read 1 alarm active, 1 unacknowledged");
        alarms.BannerText.Should().Be("alarms unknown: Filler not answering; when last read 1 active, 1 unacknowledged");
    }

    private static AlarmRowViewModel Row(AlarmsViewModel alarms, Core.Addressing.PlcAddress flag) => alarms.Rows.Single(r => r.Flag == flag.ToString());
}
