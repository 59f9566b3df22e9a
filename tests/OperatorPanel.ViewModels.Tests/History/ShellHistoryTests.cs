using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;
using OperatorPanel.ViewModels.Shell;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.History;

/// <summary>The shell keeps the open project's history: values from the moment it is loaded, the audit, the old alarm file imported once.</summary>
public sealed class ShellHistoryTests : IAsyncDisposable
{
    private static readonly PlcAddress Speed = PlcAddress.Parse("VW10");
    private readonly PanelFixture _panel = new();
    private readonly ShellViewModel _shell;
    private readonly TempFolder _folder = new();

    public ShellHistoryTests() => _shell = _panel.Shell();

    [Fact]
    public async Task History_UnsavedProject_HasNone()
    {
        _shell.History.Current.Should().BeNull();
        await _shell.Trends.RefreshAsync();

        _shell.Trends.Message.Should().StartWith("No history for this project");
    }

    [Fact]
    public async Task History_OpenedProject_IsRecordedFromTheFirstCycle()
    {
        var path = await SavedProjectAsync();
        await _shell.OpenFileAsync(path);
        await _panel.ConnectAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 1234);
        await _panel.RefreshAsync();
        await _shell.History.Current!.FlushAsync();

        var speed = _shell.History.Current.Reader.Read([(PanelFixture.Filler, Speed)], DateTimeOffset.UnixEpoch, _panel.Clock.GetUtcNow().AddMinutes(1)).Single();

        _shell.History.Current.DatabasePath.Should().Be(_panel.HistoryFolder.DatabaseFor(path, demo: false));
        speed.Samples.Select(s => s.Stored).Should().Equal(null, 1234L);
        speed.Samples[0].Quality.Should().Be(Core.Polling.ValueQuality.Bad, "recorded when the project was opened, before connecting");
    }

    [Fact]
    public async Task Write_IsAuditedWithIntentAndOutcomeAndWho()
    {
        await SavedProjectAsync();
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();

        var outcome = await _panel.Session.WriteAsync(WriteRequest.Bytes(PanelFixture.Filler, Speed, [0x00, 0x2A]));
        await _shell.History.Current!.FlushAsync();

        outcome.Should().BeOfType<WriteOutcome.Confirmed>();
        var audit = _shell.History.Current.Reader.Audit(DateTimeOffset.UnixEpoch, _panel.Clock.GetUtcNow().AddMinutes(1));
        audit.Select(a => (a.Step, a.Action, a.Target, a.OldValue, a.NewValue, a.Outcome, a.User, a.Port)).Should().Equal(
            (AuditStep.Intent, AuditAction.Write, "VW10", "16#0000", "16#002A", null, _panel.Session.User, "COM7"),
            (AuditStep.Outcome, AuditAction.Write, "VW10", "16#0000", "16#002A", "confirmed", _panel.Session.User, "COM7"));
        audit[0].Id.Should().Be(audit[1].Id, "an intent and its outcome share the action's id");
        audit[0].Symbol.Should().Be("Speed", "the project's name for VW10");
    }

    [Fact]
    public async Task Save_ProjectUnchangedInWhatIsRecorded_KeepsTheRecordingGoing()
    {
        var path = await SavedProjectAsync();
        await _shell.OpenFileAsync(path);
        await _panel.ConnectAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 1234);
        await _panel.RefreshAsync();
        var historian = _shell.History.Current!;
        await historian.FlushAsync();
        _panel.Clock.Advance(TimeSpan.FromSeconds(1));

        await _shell.SaveCommand.ExecuteAsync(null).Guarded();
        await historian.FlushAsync();

        _shell.History.Current.Should().BeSameAs(historian);
        var speed = historian.Reader.Read([(PanelFixture.Filler, Speed)], DateTimeOffset.UnixEpoch, _panel.Clock.GetUtcNow().AddMinutes(1)).Single();
        speed.Samples.Select(s => s.Stored).Should().Equal([null, 1234L], "a restarted recording would store the unchanged value again at the save");
    }

    [Fact]
    public async Task Open_OldAlarmHistoryFileBesideTheProject_IsImportedIntoTheJournalOnce()
    {
        var path = _folder.File("filler.opproj");
        ProjectFile.TrySave(PanelFixture.Project(), path, out _).Should().BeTrue();
        var file = new AlarmHistoryFile(AlarmHistoryFile.PathFor(path), _panel.Clock);
        var old = new AlarmEvent(_panel.Clock.GetUtcNow().AddHours(-2), "Filler", PanelFixture.Filler, PlcAddress.Parse("M1.0"), AlarmTransition.Raised, AlarmState.ActiveUnacknowledged, AlarmClass.Fault, "Filler jam");
        file.TryAppend([old], out _).Should().BeTrue();

        await _shell.OpenFileAsync(path);
        await _shell.AlarmsStarted;
        await _shell.OpenFileAsync(path);
        await _shell.AlarmsStarted;

        var journal = await _shell.History.Current!.Journal.SearchAsync(Historian.Journal.JournalFilter.All);
        journal.Should().ContainSingle().Which.Event.Should().Be(old);
        _shell.Alarms.Journal.Entries.Should().ContainSingle("the window shows the last day of the journal");
    }

    [Fact]
    public async Task Demo_RecordsIntoTheDemosOwnDatabase()
    {
        await using var panel = new PanelFixture();
        var demo = new SampleDemo(panel.Connector);
        var shell = panel.Shell(demo);

        await shell.DemoCommand.ExecuteAsync(null);

        shell.History.Current!.DatabasePath.Should().Be(panel.HistoryFolder.DatabaseFor(demo.SampleProjectPath, demo: true));
        shell.Dispose();
    }

    public async ValueTask DisposeAsync()
    {
        await _shell.CloseAsync();
        _shell.Dispose();
        await _panel.DisposeAsync();
        _folder.Dispose();
    }

    private async Task<string> SavedProjectAsync()
    {
        var path = _folder.File("filler.opproj");
        _panel.Files.FileToSave = path;
        await _shell.SaveAsCommand.ExecuteAsync(null).Guarded();
        return path;
    }
}
