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
    private readonly RecordingDocuments _documents = new();

    public void Dispose() => _folder.Dispose();

    [Fact]
    public void Alarm_RaisedAcknowledgedCleared_LandsInTheJournalAndItsCsvWithWhoAcknowledged()
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
        alarms.Journal.Entries.Select(e => e.Event.Transition).Should().Equal(AlarmTransition.Raised, AlarmTransition.Acknowledged, AlarmTransition.Cleared);

        _files.Answer = _folder.File("export.csv");
        alarms.Journal.ExportCsvCommand.Execute(null);
        File.ReadAllText(_files.Answer).Should().Be(
            "Time,Station,Address,Flag,Event,State,Class,Text,User\r\n"
            + $"2024-01-15T08:00:00.000Z,Filler,2,M0.0,raised,active unacknowledged,fault,{JamText},\r\n"
            + $"2024-01-15T08:00:05.000Z,Filler,2,M0.0,acknowledged,active acknowledged,fault,{JamText},maria\r\n"
            + $"2024-01-15T08:00:15.000Z,Filler,2,M0.0,cleared,cleared,fault,{JamText},\r\n");
        alarms.Journal.Message.Should().Be($"Exported 3 journal entries to {_files.Answer} (times in UTC).");
        alarms.Journal.IsMessageError.Should().BeFalse("a success is never red");
    }

    [Fact]
    public async Task Journal_ShopFloorZone_ShownInLocalTimeLikeTheAlarmTableAndExportedInUtc()
    {
        var clock = new ManualTimeProvider { LocalZone = TimeZoneInfo.CreateCustomTimeZone("Plant", TimeSpan.FromHours(2), "Plant", "Plant") };
        using var alarms = new AlarmsViewModel(AlarmProject.Create(), null, _values, clock, new AlarmServices(_files, SilentAlarmSound.Instance, _documents, _folder.Path, "maria"));
        await alarms.StartAsync();

        _values.Publish(Bit(Jam, on: true));

        var raised = new DateTimeOffset(2024, 1, 15, 10, 0, 0, TimeSpan.FromHours(2));
        alarms.Journal.Entries.Should().ContainSingle().Which.At.Should().Be(raised);
        alarms.Journal.Entries[0].At.Offset.Should().Be(TimeSpan.FromHours(2));
        Row(alarms, Jam).RaisedAt!.Value.Offset.Should().Be(TimeSpan.FromHours(2), "the table and the journal show one zone");
        _files.Answer = _folder.File("export.csv");
        alarms.Journal.ExportCsvCommand.Execute(null);
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
        alarms.Journal.Entries.Count(e => e.Event.Transition == AlarmTransition.Acknowledged).Should().Be(2);
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
        alarms.Journal.Entries.Should().ContainSingle();
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
    public async Task Journal_SavedProject_IsKeptAndTakenUpWithPendingState()
    {
        await using var historian = Historian.Historian.Open(_folder.File("line.history.db"), AlarmProject.Create(), _clock);
        using (var first = await StartedAsync(historian.Journal))
        {
            _values.Publish(Bit(Jam, on: true));
        }

        using var second = await StartedAsync(historian.Journal, readAll: false); // the line still holds Jam on

        second.Journal.Entries.Should().ContainSingle().Which.Event.Should().Be(new AlarmEvent(
            _clock.GetUtcNow(), "Filler", Station, Jam, AlarmTransition.Raised, AlarmState.ActiveUnacknowledged, AlarmClass.Fault, "Conveyor jam, \"infeed\", stop"));
        Row(second, Jam).State.Should().Be(AlarmState.ActiveUnacknowledged);
        second.UnacknowledgedCount.Should().Be(1);
        second.Message.Should().BeNull();
    }

    [Fact]
    public async Task Journal_SearchByTextAndClass_FindsOnlyThose()
    {
        await using var historian = Historian.Historian.Open(_folder.File("line.history.db"), AlarmProject.Create(), _clock);
        using var alarms = await StartedAsync(historian.Journal);
        _values.Publish([.. Bit(Jam, on: true), .. Bit(LowLevel, on: true), .. Bit(DoorOpen, on: true)]);

        alarms.Journal.Text = "door";
        await alarms.Journal.SearchCommand.ExecuteAsync(null);
        alarms.Journal.Entries.Select(e => e.Event.Flag).Should().Equal(DoorOpen);

        (alarms.Journal.Text, alarms.Journal.SelectedClass) = (string.Empty, "Warning");
        await alarms.Journal.SearchCommand.ExecuteAsync(null);
        alarms.Journal.Entries.Select(e => e.Event.Flag).Should().BeEquivalentTo([LowLevel, DoorOpen]);
        alarms.Journal.Message.Should().Be("2 entries: the last 24 hours, all stations, warning alarms");
    }

    [Fact]
    public async Task Journal_Print_WritesAnHtmlPageAndOpensIt()
    {
        using var alarms = await StartedAsync(null);
        _values.Publish(Bit(Jam, on: true));

        alarms.Journal.PrintCommand.Execute(null);

        var page = _documents.Opened.Should().ContainSingle().Subject;
        Path.GetDirectoryName(page).Should().Be(_folder.Path);
        File.ReadAllText(page).Should().Contain("<h1>Alarm journal: Bottling</h1>").And.Contain("Conveyor jam, &quot;infeed&quot;, stop").And.Contain("window.print()");
    }

    [Fact]
    public void ExportCsv_OperatorCancels_WritesNothing()
    {
        using var alarms = Create();
        _values.Publish(Bit(Jam, on: true));

        alarms.Journal.ExportCsvCommand.Execute(null);

        _files.Asked.Should().Equal("Export alarm journal");
        alarms.Journal.Message.Should().Be("0 entries: the last 24 hours, all stations, all classes", "the start's search, unchanged: nothing was exported");
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

    /// <summary>The view model started; with <paramref name="readAll"/> every flag then read once as off, as after the first poll of a station that answers.</summary>
    private AlarmsViewModel Create(bool readAll = true)
    {
        var alarms = New(null);
        alarms.StartAsync().IsCompletedSuccessfully.Should().BeTrue("without a journal the window starts at once");
        ReadAll(readAll);
        return alarms;
    }

    private async Task<AlarmsViewModel> StartedAsync(Historian.Journal.AlarmJournal? journal, bool readAll = true)
    {
        var alarms = New(journal);
        await alarms.StartAsync();
        ReadAll(readAll);
        return alarms;
    }

    private void ReadAll(bool readAll)
    {
        if (readAll)
        {
            _values.Publish([.. Bit(Jam, on: false), .. Bit(LowLevel, on: false), .. Bit(DoorOpen, on: false)]);
        }
    }

    private AlarmsViewModel New(Historian.Journal.AlarmJournal? journal) =>
        new(AlarmProject.Create(), journal, _values, _clock, new AlarmServices(_files, SilentAlarmSound.Instance, _documents, _folder.Path, "maria"));
}
