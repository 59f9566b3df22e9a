using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Polling;
using OperatorPanel.TestKit;
using OperatorPanel.ViewModels.Alarms;
using OperatorPanel.ViewModels.Tests.Fakes;
using static OperatorPanel.ViewModels.Tests.Fakes.AlarmProject;

namespace OperatorPanel.ViewModels.Tests.Alarms;

/// <summary>
/// The alarm window: raise, acknowledge, clear, history and CSV, order, hidden rows, banner. Over 300 lines: these share
/// one fixture (the three-alarm project read once as all off); unknown alarms are AlarmsUnknownTests.
/// </summary>
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
        var jam = Row(alarms, Jam);

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
        alarms.Message.Should().Be($"Exported 3 history entries to {_files.Answer} (times in UTC).");
        alarms.IsMessageError.Should().BeFalse("a success is never red");
    }

    [Fact]
    public void History_ShopFloorZone_ShownInLocalTimeLikeTheAlarmTableAndExportedInUtc()
    {
        var clock = new ManualTimeProvider { LocalZone = TimeZoneInfo.CreateCustomTimeZone("Plant", TimeSpan.FromHours(2), "Plant", "Plant") };
        using var alarms = new AlarmsViewModel(AlarmProject.Create(), null, _values, clock, _files);

        _values.Publish(Bit(Jam, on: true));

        var raised = new DateTimeOffset(2024, 1, 15, 10, 0, 0, TimeSpan.FromHours(2));
        alarms.History.Should().ContainSingle().Which.At.Should().Be(raised);
        alarms.History[0].At.Offset.Should().Be(TimeSpan.FromHours(2));
        Row(alarms, Jam).RaisedAt!.Value.Offset.Should().Be(TimeSpan.FromHours(2), "the table and the history show one zone");
        _files.Answer = _folder.File("export.csv");
        alarms.ExportCsvCommand.Execute(null);
        File.ReadAllText(_files.Answer).Should().Contain("2024-01-15T08:00:00.000Z,Filler", "exports are in UTC");
    }

    [Fact]
    public void StateText_NeverRaisedAndAlarmWithoutAcknowledgement_ReadAsTheOperatorSeesThem()
    {
        using var alarms = Create();
        var jam = Row(alarms, Jam);
        var lowLevel = Row(alarms, LowLevel);

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

        Row(alarms, Jam).State.Should().Be(AlarmState.ActiveAcknowledged);
        Row(alarms, DoorOpen).State.Should().Be(AlarmState.Cleared);
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

        Row(alarms, DoorOpen).State.Should().Be(AlarmState.Cleared);
        Row(alarms, Jam).State.Should().Be(AlarmState.ActiveUnacknowledged);
        alarms.History.Should().ContainSingle();
    }

    [Fact]
    public void AlarmWithoutAcknowledgement_Clears_LeavesTheListWithoutAcknowledging()
    {
        using var alarms = Create();
        _values.Publish(Bit(LowLevel, on: true));
        Row(alarms, LowLevel).State.Should().Be(AlarmState.ActiveAcknowledged);
        alarms.UnacknowledgedCount.Should().Be(0);

        _values.Publish(Bit(LowLevel, on: false));

        Row(alarms, LowLevel).State.Should().Be(AlarmState.Cleared);
        alarms.AcknowledgeCommand.CanExecute(Row(alarms, LowLevel)).Should().BeFalse();
    }

    [Fact]
    public void ClearedUnacknowledged_RaisedAgain_IsActiveUnacknowledgedWithNewRaiseTime()
    {
        using var alarms = Create();
        _values.Publish(Bit(Jam, on: true));
        _values.Publish(Bit(Jam, on: false));
        _clock.Advance(TimeSpan.FromMinutes(1));

        _values.Publish(Bit(Jam, on: true));

        Row(alarms, Jam).State.Should().Be(AlarmState.ActiveUnacknowledged);
        Row(alarms, Jam).RaisedAt.Should().Be(_clock.GetUtcNow());
        Row(alarms, Jam).ClearedAt.Should().BeNull();
    }

    [Fact]
    public void History_SavedProject_IsPersistedAndReloadedWithPendingState()
    {
        var project = _folder.File("line.opproj");
        using (var first = Create(project))
        {
            _values.Publish(Bit(Jam, on: true));
        }

        using var second = Create(project, readAll: false); // the line still holds Jam on

        second.History.Should().ContainSingle().Which.Event.Should().Be(new AlarmEvent(
            _clock.GetUtcNow(), "Filler", Station, Jam, AlarmTransition.Raised, AlarmState.ActiveUnacknowledged, AlarmClass.Fault, "Conveyor jam, \"infeed\", stop"));
        Row(second, Jam).State.Should().Be(AlarmState.ActiveUnacknowledged);
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
        alarms.IsMessageError.Should().BeTrue();
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

    [Fact]
    public void Rows_AlarmsChangeState_PendingComeFirstByStateThenClassThenLatestRaise()
    {
        using var alarms = Create();
        Flags(alarms).Should().Equal("M0.0", "V10.1", "M0.1");

        _values.Publish(Bit(DoorOpen, on: true));
        _clock.Advance(TimeSpan.FromSeconds(1));
        _values.Publish(Bit(LowLevel, on: true));
        _clock.Advance(TimeSpan.FromSeconds(1));
        _values.Publish(Bit(Jam, on: true));
        Flags(alarms).Should().Equal(["M0.0", "M0.1", "V10.1"], "active unacknowledged (fault, then warning) before active acknowledged");

        alarms.AcknowledgeCommand.Execute(Row(alarms, Jam));
        alarms.AcknowledgeCommand.Execute(Row(alarms, DoorOpen));
        Flags(alarms).Should().Equal(["M0.0", "V10.1", "M0.1"], "all active acknowledged: the fault, then the warning raised last");

        _values.Publish([.. Bit(Jam, on: false), .. Bit(LowLevel, on: false)]);
        _clock.Advance(TimeSpan.FromSeconds(1));
        _values.Publish(Bit(Jam, on: true));
        _values.Publish(Bit(Jam, on: false));
        Flags(alarms).Should().Equal(["M0.1", "M0.0", "V10.1"], "active, then cleared unacknowledged, then cleared");
    }

    [Fact]
    public void AlarmOrder_ClearedAlarms_RaisedBeforeComeBeforeNeverRaisedAndProjectOrderBreaksTies()
    {
        var project = AlarmProject.Create().Stations[0];
        AlarmStatus Status(int i, DateTimeOffset? raisedAt) =>
            new("Filler", Station, project.Alarms[i], AlarmState.Cleared, raisedAt, raisedAt, null);
        var morning = new DateTimeOffset(2024, 1, 15, 8, 0, 0, TimeSpan.Zero);

        AlarmOrder.Compare(Status(1, null), 1, Status(2, morning), 2).Should().BePositive();
        AlarmOrder.Compare(Status(1, morning), 1, Status(2, morning), 2).Should().BeNegative();
        AlarmOrder.Compare(Status(2, morning), 2, Status(0, null), 0).Should().BePositive("a fault comes before a warning whatever their times");
    }

    [Fact]
    public void HiddenPendingText_PaneShowsFewerRowsThanPending_CountsThoseAboveAndBelow()
    {
        using var alarms = Create();
        _values.Publish([.. Bit(Jam, on: true), .. Bit(DoorOpen, on: true), .. Bit(LowLevel, on: true)]);
        alarms.HiddenPendingText.Should().BeNull("the view has not said what it shows");

        alarms.ShowVisibleRows(0, 1);
        alarms.HiddenPendingText.Should().Be("2 more pending alarms below");
        alarms.FirstHiddenPending.Should().BeSameAs(Row(alarms, DoorOpen));

        alarms.ShowVisibleRows(1, 1);
        alarms.HiddenPendingText.Should().Be("1 pending alarm above, 1 below");
        alarms.FirstHiddenPending.Should().BeSameAs(Row(alarms, Jam));

        alarms.ShowVisibleRows(2, 1);
        alarms.HiddenPendingText.Should().Be("2 pending alarms above");

        alarms.ShowVisibleRows(0, 3);
        alarms.HiddenPendingText.Should().BeNull();
        alarms.FirstHiddenPending.Should().BeNull();
    }

    [Fact]
    public void HiddenPendingText_AlarmRaisedWhileScrolledPastTheTop_CountsItAbove()
    {
        using var alarms = Create();
        alarms.ShowVisibleRows(1, 2);
        alarms.HiddenPendingText.Should().BeNull("nothing is pending");

        _values.Publish(Bit(DoorOpen, on: true));

        Flags(alarms)[0].Should().Be("M0.1");
        alarms.HiddenPendingText.Should().Be("1 pending alarm above");

        alarms.AcknowledgeCommand.Execute(Row(alarms, DoorOpen));
        _values.Publish(Bit(DoorOpen, on: false));
        alarms.HiddenPendingText.Should().BeNull("the alarm is no longer pending");
    }

    [Fact]
    public void MostUrgent_SeveralPending_IsTheFirstInOrderAndTheRestAreCounted()
    {
        using var alarms = Create();
        alarms.MostUrgent.Should().BeNull();
        alarms.MorePendingText.Should().BeNull();

        _values.Publish([.. Bit(DoorOpen, on: true), .. Bit(LowLevel, on: true)]);
        alarms.MostUrgent.Should().BeSameAs(Row(alarms, DoorOpen), "active unacknowledged before active acknowledged");
        alarms.MorePendingText.Should().Be("and 1 more");

        _values.Publish(Bit(Jam, on: true));
        alarms.MostUrgent.Should().BeSameAs(Row(alarms, Jam), "a fault before a warning");
        alarms.MorePendingText.Should().Be("and 2 more");

        alarms.AcknowledgeAllCommand.Execute(null);
        _values.Publish([.. Bit(Jam, on: false), .. Bit(DoorOpen, on: false)]);
        alarms.MostUrgent.Should().BeSameAs(Row(alarms, LowLevel));
        alarms.MorePendingText.Should().BeNull();
    }

    private static AlarmRowViewModel Row(AlarmsViewModel alarms, Core.Addressing.PlcAddress flag) => alarms.Rows.Single(r => r.Flag == flag.ToString());

    private static List<string> Flags(AlarmsViewModel alarms) => [.. alarms.Rows.Select(r => r.Flag)];

    /// <summary>The view model; with <paramref name="readAll"/> every flag then read once as off, as after the first poll of a station that answers.</summary>
    private AlarmsViewModel Create(string? projectPath = null, bool readAll = true)
    {
        var alarms = new AlarmsViewModel(AlarmProject.Create(), projectPath, _values, _clock, _files);
        if (readAll)
        {
            _values.Publish([.. Bit(Jam, on: false), .. Bit(LowLevel, on: false), .. Bit(DoorOpen, on: false)]);
        }

        return alarms;
    }
}
