using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Polling;
using OperatorPanel.TestKit;
using OperatorPanel.ViewModels.Alarms;
using OperatorPanel.ViewModels.Tests.Fakes;
using static OperatorPanel.ViewModels.Tests.Fakes.AlarmProject;

namespace OperatorPanel.ViewModels.Tests.Alarms;

public sealed class AlarmsViewModelTests : IDisposable
{
    private const string JamText = "\"Conveyor jam, \"\"infeed\"\", stop\"";
    private readonly ManualTimeProvider _clock = new();
    private readonly FakeLineValues _values = new();
    private readonly ScriptedFileDialogs _files = new();
    private readonly TempFolder _folder = new();

    public void Dispose() => _folder.Dispose();

    [Fact]
    public void Alarm_RaisedAcknowledgedCleared_LandsInHistoryAndCsv()
    {
        using var alarms = Create();
        var jam = alarms.Rows[0];

        _values.Publish(Bit(Jam, on: true));
        jam.State.Should().Be(AlarmState.ActiveUnacknowledged);
        jam.RaisedAt.Should().Be(_clock.GetUtcNow());
        _clock.Advance(TimeSpan.FromSeconds(5));
        alarms.AcknowledgeCommand.Execute(jam);
        jam.State.Should().Be(AlarmState.ActiveAcknowledged);
        _clock.Advance(TimeSpan.FromSeconds(10));
        _values.Publish(Bit(Jam, on: false));

        jam.State.Should().Be(AlarmState.Cleared);
        jam.IsPending.Should().BeFalse();
        jam.AcknowledgedAt.Should().Be(new DateTimeOffset(2024, 1, 15, 8, 0, 5, TimeSpan.Zero));
        jam.ClearedAt.Should().Be(new DateTimeOffset(2024, 1, 15, 8, 0, 15, TimeSpan.Zero));
        alarms.History.Select(e => e.Transition).Should().Equal(AlarmTransition.Raised, AlarmTransition.Acknowledged, AlarmTransition.Cleared);

        _files.Answer = _folder.File("export.csv");
        alarms.ExportCsvCommand.Execute(null);
        File.ReadAllText(_files.Answer).Should().Be(
            "Time,Station,Address,Flag,Event,State,Class,Text\r\n"
            + $"2024-01-15T08:00:00.000Z,Filler,2,M0.0,raised,active unacknowledged,fault,{JamText}\r\n"
            + $"2024-01-15T08:00:05.000Z,Filler,2,M0.0,acknowledged,active acknowledged,fault,{JamText}\r\n"
            + $"2024-01-15T08:00:15.000Z,Filler,2,M0.0,cleared,cleared,fault,{JamText}\r\n");
        alarms.Message.Should().Be($"Exported 3 history entries to {_files.Answer}.");
    }

    [Fact]
    public void StateText_NeverRaisedAndAlarmWithoutAcknowledgement_ReadAsTheOperatorSeesThem()
    {
        using var alarms = Create();
        var jam = alarms.Rows.Single(r => r.Flag == "M0.0");
        var lowLevel = alarms.Rows.Single(r => r.Flag == "V10.1");

        jam.StateText.Should().Be("not raised");
        _values.Publish([.. Bit(Jam, on: true), .. Bit(LowLevel, on: true)]);
        jam.StateText.Should().Be("active unacknowledged");
        lowLevel.StateText.Should().Be("active", "nobody acknowledged an alarm that needs no acknowledgement");
        _values.Publish([.. Bit(Jam, on: false), .. Bit(LowLevel, on: false)]);
        jam.StateText.Should().Be("cleared unacknowledged");
        lowLevel.StateText.Should().Be("cleared");
    }

    [Fact]
    public void AcknowledgeAll_OneActiveOneCleared_AcknowledgesBothAndCountsFollow()
    {
        using var alarms = Create();
        _values.Publish([.. Bit(Jam, on: true), .. Bit(DoorOpen, on: true)]);
        _values.Publish(Bit(DoorOpen, on: false));
        alarms.ActiveCount.Should().Be(1);
        alarms.UnacknowledgedCount.Should().Be(2);
        alarms.Summary.Should().Be("1 alarm active, 2 unacknowledged");

        alarms.AcknowledgeAllCommand.Execute(null);

        alarms.Rows[0].State.Should().Be(AlarmState.ActiveAcknowledged);
        alarms.Rows[2].State.Should().Be(AlarmState.Cleared);
        alarms.UnacknowledgedCount.Should().Be(0);
        alarms.AcknowledgeAllCommand.CanExecute(null).Should().BeFalse();
        alarms.History.Count(e => e.Transition == AlarmTransition.Acknowledged).Should().Be(2);
    }

    [Fact]
    public void Counts_AlarmRaised_RaisePropertyChangedForTheStatusBar()
    {
        using var alarms = Create();
        var changed = new List<string?>();
        alarms.PropertyChanged += (_, e) => changed.Add(e.PropertyName);

        _values.Publish(Bit(Jam, on: true));

        changed.Should().Contain([nameof(AlarmsViewModel.ActiveCount), nameof(AlarmsViewModel.UnacknowledgedCount), nameof(AlarmsViewModel.Summary)]);
    }

    [Theory]
    [InlineData(ValueQuality.Stale)]
    [InlineData(ValueQuality.Bad)]
    public void UntrustedValue_NeitherRaisesNorClears(ValueQuality quality)
    {
        using var alarms = Create();
        _values.Publish(Bit(DoorOpen, on: true, quality));
        _values.Publish(Bit(Jam, on: true));
        _values.Publish(Bit(Jam, on: false, quality));

        alarms.Rows[2].State.Should().Be(AlarmState.Cleared);
        alarms.Rows[0].State.Should().Be(AlarmState.ActiveUnacknowledged);
        alarms.History.Should().ContainSingle();
    }

    [Fact]
    public void AlarmWithoutAcknowledgement_Clears_LeavesTheListWithoutAcknowledging()
    {
        using var alarms = Create();
        _values.Publish(Bit(LowLevel, on: true));
        alarms.Rows[1].State.Should().Be(AlarmState.ActiveAcknowledged);
        alarms.UnacknowledgedCount.Should().Be(0);

        _values.Publish(Bit(LowLevel, on: false));

        alarms.Rows[1].State.Should().Be(AlarmState.Cleared);
        alarms.AcknowledgeCommand.CanExecute(alarms.Rows[1]).Should().BeFalse();
    }

    [Fact]
    public void ClearedUnacknowledged_RaisedAgain_IsActiveUnacknowledgedWithNewRaiseTime()
    {
        using var alarms = Create();
        _values.Publish(Bit(Jam, on: true));
        _values.Publish(Bit(Jam, on: false));
        _clock.Advance(TimeSpan.FromMinutes(1));

        _values.Publish(Bit(Jam, on: true));

        alarms.Rows[0].State.Should().Be(AlarmState.ActiveUnacknowledged);
        alarms.Rows[0].RaisedAt.Should().Be(_clock.GetUtcNow());
        alarms.Rows[0].ClearedAt.Should().BeNull();
    }

    [Fact]
    public void History_SavedProject_IsPersistedAndReloadedWithPendingState()
    {
        var project = _folder.File("line.opproj");
        using (var first = Create(project))
        {
            _values.Publish(Bit(Jam, on: true));
        }

        using var second = Create(project);

        second.History.Should().ContainSingle().Which.Should().Be(new AlarmEvent(
            _clock.GetUtcNow(), "Filler", Station, Jam, AlarmTransition.Raised, AlarmState.ActiveUnacknowledged, AlarmClass.Fault, "Conveyor jam, \"infeed\", stop"));
        second.Rows[0].State.Should().Be(AlarmState.ActiveUnacknowledged);
        second.UnacknowledgedCount.Should().Be(1);
        second.Message.Should().BeNull();
        File.Exists(_folder.File("line.alarms.jsonl")).Should().BeTrue();
    }

    [Fact]
    public void History_CorruptFile_IsSetAsideWithAMessageAndANewHistoryStarts()
    {
        var history = _folder.File("line.alarms.jsonl");
        File.WriteAllText(history, "{\"time\":\"yesterday\"}\nnot json at all\n");

        using var alarms = Create(_folder.File("line.opproj"));

        alarms.History.Should().BeEmpty();
        alarms.Message.Should().Be($"The alarm history {history} is corrupt (line 1: time is missing or not an ISO 8601 UTC time); "
            + $"it was kept as {history}.corrupt-20240115T080000Z and a new history was started.");
        File.ReadAllText(history + ".corrupt-20240115T080000Z").Should().StartWith("{\"time\":\"yesterday\"}");
        _values.Publish(Bit(Jam, on: true));
        File.ReadAllLines(history).Should().ContainSingle();
    }

    [Fact]
    public void ExportCsv_OperatorCancels_WritesNothing()
    {
        using var alarms = Create();
        _values.Publish(Bit(Jam, on: true));

        alarms.ExportCsvCommand.Execute(null);

        _files.Asked.Should().Equal("Export alarm history");
        alarms.Message.Should().BeNull();
        Directory.EnumerateFiles(_folder.Path).Should().BeEmpty();
    }

    [Fact]
    public void Dispose_StopsListening()
    {
        var alarms = Create();
        alarms.Dispose();

        _values.Publish(Bit(Jam, on: true));

        alarms.ActiveCount.Should().Be(0);
    }

    private AlarmsViewModel Create(string? projectPath = null) =>
        new(AlarmProject.Create(), projectPath, _values, _clock, _files);
}
