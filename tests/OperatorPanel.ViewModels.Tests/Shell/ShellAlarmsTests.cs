using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.ViewModels.Shell;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Shell;

public sealed class ShellAlarmsTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new(WithAlarms());
    private readonly ShellViewModel _shell;
    private readonly TempFolder _folder = new();

    public ShellAlarmsTests() => _shell = _panel.Shell();

    [Fact]
    public async Task Alarm_RaisedOnTheSimulatedPlcWhilePaneHidden_ShowsInAlarmsAndSummary()
    {
        _shell.Panes.Single(p => p.ContentId == "Alarms").IsVisible = false;
        var changed = new List<string?>();
        _shell.PropertyChanged += (_, e) => changed.Add(e.PropertyName);
        await _panel.ConnectAsync();

        _panel.Plc.Memory.SetBit(ProtocolArea.M, 1, 0, true);
        _panel.Plc.Memory.SetBit(ProtocolArea.M, 1, 1, true);
        await _panel.RefreshAsync();

        _shell.Alarms.Rows.Select(r => r.State).Should().Equal(AlarmState.ActiveUnacknowledged, AlarmState.ActiveUnacknowledged);
        _shell.ActiveAlarmCount.Should().Be(2);
        _shell.UnacknowledgedAlarmCount.Should().Be(2);
        _shell.AlarmSummary.Should().Be("2 active, 2 unacknowledged");
        changed.Should().Contain(nameof(ShellViewModel.AlarmSummary));

        _shell.Alarms.AcknowledgeCommand.Execute(_shell.Alarms.Rows[0]);
        _panel.Plc.Memory.SetBit(ProtocolArea.M, 1, 1, false);
        await _panel.RefreshAsync();

        _shell.AlarmSummary.Should().Be("1 active, 1 unacknowledged");
        _shell.Alarms.Journal.Entries.Select(e => e.Event.Transition).Should().Equal(
            AlarmTransition.Raised, AlarmTransition.Raised, AlarmTransition.Acknowledged, AlarmTransition.Cleared);
    }

    [Fact]
    public async Task Alarms_NoAlarmYet_SummarySaysNoAlarmsAndPaneIsListed()
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();

        _shell.AlarmSummary.Should().Be("no alarms");
        _shell.Panes.Single(p => p.ContentId == "Alarms").Content.Should().BeSameAs(_shell.Alarms);
    }

    [Fact]
    public async Task Alarms_ProjectReplaced_NewAlarmsOldOneDeaf()
    {
        var old = _shell.Alarms;
        var path = _folder.File("capper.opproj");
        ProjectFile.TrySave(PanelFixture.Project() with { Name = "Capper" }, path, out _).Should().BeTrue();
        _panel.Files.FileToOpen = path;

        await _shell.OpenCommand.ExecuteAsync(null).Guarded();
        await _panel.ConnectAsync();
        _panel.Plc.Memory.SetBit(ProtocolArea.M, 1, 0, true);
        await _panel.RefreshAsync();

        _shell.Alarms.Should().NotBeSameAs(old);
        _shell.Panes.Single(p => p.ContentId == "Alarms").Content.Should().BeSameAs(_shell.Alarms, "the pane shows the new project's alarms");
        _shell.Alarms.Rows.Should().BeEmpty();
        old.Journal.Entries.Should().BeEmpty("the old project's window was disposed and hears nothing");
        _shell.AlarmSummary.Should().Be("no alarms");
    }

    [Fact]
    public async Task Alarms_ProjectSavedAs_JournalKeptInItsHistoryDatabase()
    {
        var path = _folder.File("filler.opproj");
        _panel.Files.FileToSave = path;
        await _shell.SaveAsCommand.ExecuteAsync(null).Guarded();
        await _shell.AlarmsStarted;
        await _panel.ConnectAsync();

        _panel.Plc.Memory.SetBit(ProtocolArea.M, 1, 0, true);
        await _panel.RefreshAsync();

        _shell.History.Current!.DatabasePath.Should().Be(_panel.HistoryFolder.DatabaseFor(path, demo: false));
        var found = await _shell.History.Current.Journal.SearchAsync(Historian.Journal.JournalFilter.All);
        found.Should().ContainSingle().Which.Event.Text.Should().Be("Filler jam");
    }

    public async ValueTask DisposeAsync()
    {
        _shell.Dispose();
        await _panel.DisposeAsync();
        _folder.Dispose();
    }

    private static PanelProject WithAlarms()
    {
        var project = PanelFixture.Project();
        var station = project.Stations[0] with
        {
            Alarms =
            [
                new AlarmDefinition(PlcAddress.Parse("M1.0"), "Filler jam", AlarmClass.Fault, AcknowledgementRequired: true),
                new AlarmDefinition(PlcAddress.Parse("M1.1"), "Bottle missing", AlarmClass.Warning, AcknowledgementRequired: true),
            ],
        };
        return project with { Stations = [station] };
    }
}
