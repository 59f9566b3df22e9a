using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Shell;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Shell;

public sealed class ShellViewModelTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new();
    private readonly ShellViewModel _shell;
    private readonly string _folder = Directory.CreateTempSubdirectory("opanel-shell-").FullName;

    public ShellViewModelTests() => _shell = _panel.Shell(new SampleDemo(_panel.Connector));

    [Fact]
    public async Task Title_ProjectEdited_NameWithStarUntilSaved()
    {
        _shell.Title.Should().Be("Filler line - Operator Panel");

        await MakeDirtyAsync();

        _shell.Title.Should().Be("Filler line * - Operator Panel");
        _panel.Files.FileToSave = Path.Combine(_folder, "filler.opproj");
        await _shell.SaveCommand.ExecuteAsync(null).Guarded();
        _shell.Title.Should().Be("Filler line - Operator Panel");
        _shell.IsDirty.Should().BeFalse();
    }

    [Fact]
    public async Task Close_UnsavedAnswerCancel_StaysOpenWithTheProject()
    {
        await MakeDirtyAsync();
        var project = _panel.Session.Project;
        _panel.Dialogs.SaveAnswers.Enqueue(SaveChangesAnswer.Cancel);

        var closed = await _shell.CloseAsync().Guarded();

        closed.Should().BeFalse();
        _panel.Dialogs.Questions.Should().Equal("Save changes to Filler line?");
        _panel.Session.Project.Should().BeSameAs(project);
        _shell.IsDirty.Should().BeTrue();
        _panel.Session.IsConnected.Should().BeTrue();
    }

    [Fact]
    public async Task Close_UnsavedAnswerDiscard_ClosesWithoutSaving()
    {
        await MakeDirtyAsync();
        _panel.Dialogs.SaveAnswers.Enqueue(SaveChangesAnswer.Discard);

        var closed = await _shell.CloseAsync().Guarded();

        closed.Should().BeTrue();
        _panel.Session.IsConnected.Should().BeFalse();
        Directory.GetFiles(_folder).Should().BeEmpty();
    }

    [Fact]
    public async Task Close_PortHangsInItsClose_ClosesAfterTwoSecondsAndLogsIt()
    {
        var hanging = new HangingCloseConnector(_panel.Connector);
        var shell = new ShellViewModel(_panel.Session, _panel.Options, PanelFixture.Services(_panel) with { Connector = hanging }, _panel.Clock, _panel.Logger);
        await shell.ConnectCommand.ExecuteAsync(null).Guarded();

        var closing = shell.CloseAsync();
        _panel.Clock.Advance(ShellViewModel.CloseWait - TimeSpan.FromMilliseconds(1));
        closing.IsCompleted.Should().BeFalse("the panel gives the port its two seconds");
        _panel.Clock.Advance(TimeSpan.FromMilliseconds(1));
        var closed = await closing.Guarded();

        closed.Should().BeTrue();
        ShellViewModel.CloseWait.Should().Be(TimeSpan.FromSeconds(2));
        _panel.Log.Messages.Should().Contain("The line did not close within 2 s (COM7); the panel closes without waiting for it");
        hanging.Release.SetResult();
    }

    [Fact]
    public async Task Close_UnsavedAnswerSave_SavesThenCloses()
    {
        await MakeDirtyAsync();
        _panel.Dialogs.SaveAnswers.Enqueue(SaveChangesAnswer.Save);
        var path = Path.Combine(_folder, "filler.opproj");
        _panel.Files.FileToSave = path;

        var closed = await _shell.CloseAsync().Guarded();

        closed.Should().BeTrue();
        var saved = ProjectFile.Load(path);
        saved.Ok.Should().BeTrue();
        saved.Project!.Stations[0].Tags.Select(t => t.Symbol).Should().Contain("Count");
    }

    [Fact]
    public async Task Close_UnsavedSaveDialogCancelled_StaysOpen()
    {
        await MakeDirtyAsync();
        _panel.Dialogs.SaveAnswers.Enqueue(SaveChangesAnswer.Save);
        _panel.Files.FileToSave = null;

        var closed = await _shell.CloseAsync().Guarded();

        closed.Should().BeFalse();
        _shell.IsDirty.Should().BeTrue();
    }

    [Fact]
    public async Task Close_NothingUnsaved_ClosesWithoutAsking()
    {
        var closed = await _shell.CloseAsync().Guarded();

        closed.Should().BeTrue();
        _panel.Dialogs.Questions.Should().BeEmpty();
    }

    [Fact]
    public async Task Open_CorruptFile_MessageAndCurrentProjectKept()
    {
        await _panel.ConnectAsync();
        var project = _panel.Session.Project;
        var path = Path.Combine(_folder, "broken.opproj");
        await File.WriteAllTextAsync(path, "{ \"schemaVersion\": 1, \"name\": ");
        _panel.Files.FileToOpen = path;

        await _shell.OpenCommand.ExecuteAsync(null).Guarded();

        var error = _panel.Dialogs.Errors.Should().ContainSingle().Subject;
        error.Title.Should().Be("Project not opened");
        error.Message.Should().StartWith($"{path} is not a usable project file; the current project stays open.").And.Contain("line 1");
        _panel.Session.Project.Should().BeSameAs(project);
        _panel.Session.IsConnected.Should().BeTrue();
        _shell.Title.Should().Be("Filler line - Operator Panel");
        _panel.Session.StatusLine.IsError.Should().BeTrue();
    }

    [Fact]
    public async Task Open_FileBeyondTheProblemLimit_MessageShowsFirstProblemsHowManyLeftOutAndThatTheLoaderStopped()
    {
        var path = Path.Combine(_folder, "many-broken-stations.opproj");
        await File.WriteAllTextAsync(
            path, "{\"schemaVersion\":1,\"name\":\"x\",\"refresh\":{\"mode\":\"continuous\"},\"stations\":[" + string.Join(',', Enumerable.Repeat("{}", 300)) + "]}");
        _panel.Files.FileToOpen = path;

        await _shell.OpenCommand.ExecuteAsync(null).Guarded();

        var lines = _panel.Dialogs.Errors.Should().ContainSingle().Subject.Message.Split(Environment.NewLine);
        lines.Should().HaveCount(11);
        lines[1].Should().Be("$.stations[0]: missing required property 'name'");
        lines[9].Should().Be("(and 92 more)");
        lines[10].Should().Be("file: more than 100 problems; the rest are not listed: correct these and load the file again");
    }

    [Fact]
    public async Task Open_UnsavedAnswerCancel_NoFileAskedAndProjectKept()
    {
        await MakeDirtyAsync();
        var project = _panel.Session.Project;
        _panel.Dialogs.SaveAnswers.Enqueue(SaveChangesAnswer.Cancel);
        _panel.Files.FileToOpen = Path.Combine(_folder, "never-read.opproj");

        await _shell.OpenCommand.ExecuteAsync(null).Guarded();

        _panel.Session.Project.Should().BeSameAs(project);
        _panel.Dialogs.Errors.Should().BeEmpty("the file was never opened");
        _shell.IsDirty.Should().BeTrue();
    }

    [Fact]
    public async Task New_NothingUnsaved_StarterProjectUnsavedAndUntitled()
    {
        await _shell.NewCommand.ExecuteAsync(null).Guarded();

        _shell.Title.Should().Be("Untitled * - Operator Panel");
        _shell.ProjectPath.Should().BeNull();
        _shell.Inputs.Groups.Should().NotBeEmpty("the starter project symbolises every local input");
    }

    [Fact]
    public async Task Open_ValidFile_ReplacesProjectCleanAndDisconnected()
    {
        var path = Path.Combine(_folder, "other.opproj");
        ProjectFile.TrySave(PanelFixture.Project() with { Name = "Capper" }, path, out _).Should().BeTrue();
        await _panel.ConnectAsync();
        _panel.Files.FileToOpen = path;

        await _shell.OpenCommand.ExecuteAsync(null).Guarded();

        _shell.Title.Should().Be("Capper - Operator Panel");
        _shell.ProjectPath.Should().Be(path);
        _panel.Session.IsConnected.Should().BeFalse();
        _shell.ConnectCommand.CanExecute(null).Should().BeTrue();
    }

    [Fact]
    public async Task Open_CompactStationWithAllowStop_OpensAndSaysWhyStopCannotWork()
    {
        var path = Path.Combine(_folder, "compact-stop.opproj");
        var project = PanelFixture.Project();
        ProjectFile.TrySave(project with { Stations = [project.Stations[0] with { Compact = true, AllowStop = true }] }, path, out _).Should().BeTrue();
        _panel.Files.FileToOpen = path;

        await _shell.OpenCommand.ExecuteAsync(null).Guarded();

        _shell.ProjectPath.Should().Be(path, "the panel reads and writes such a station as any other");
        _panel.Dialogs.Errors.Should().BeEmpty();
        _panel.Session.StatusLine.IsError.Should().BeTrue();
        _panel.Session.StatusLine.Text.Should().StartWith($"Opened {_shell.ProjectName}; {project.Stations[0].Name} (station 2) has \"compact\": true and \"allowStop\": true, but a compact handler has no STOP")
            .And.EndWith("for the compact handler without it (File > Edit project)");
    }

    [Fact]
    public async Task Open_WritableTagInTheHandlersOwnVBytes_OpensAndSaysItsWritesWillBeRefused()
    {
        var path = Path.Combine(_folder, "tag-in-handler.opproj");
        var project = PanelFixture.Project();
        var spare = new ProjectTag("Spare", Core.Addressing.PlcAddress.Parse("VW8000"), DisplayFormat.Unsigned, true, string.Empty);
        var station = project.Stations[0] with { Tags = project.Stations[0].Tags.Add(spare) };
        ProjectFile.TrySave(project with { Stations = [station] }, path, out _).Should().BeTrue();
        _panel.Files.FileToOpen = path;

        await _shell.OpenCommand.ExecuteAsync(null).Guarded();

        _shell.ProjectPath.Should().Be(path, "the panel opens the project and refuses the tag's writes when they are tried");
        _panel.Session.StatusLine.IsError.Should().BeTrue();
        _panel.Session.StatusLine.Text.Should().StartWith($"Opened {_shell.ProjectName}; tag Spare (VW8000) is writable, but VW8000 is in the handler's own V bytes VB7586-VB8191")
            .And.EndWith("(File > Edit project)");
    }

    [Fact]
    public async Task Demo_SampleProject_OpensOnTheSimulatedLineWithLiveValues()
    {
        await _shell.DemoCommand.ExecuteAsync(null).Guarded();
        await _shell.RefreshNowCommand.ExecuteAsync(null).Guarded();

        _shell.IsDemo.Should().BeTrue();
        _shell.Title.Should().Be("Bottling line 1 (demo) - Operator Panel");
        _shell.Session.IsConnected.Should().BeTrue();
        _shell.Stations.Should().OnlyContain(s => s.Health == ViewModels.Session.StationHealth.Online);
        _shell.Inputs.Groups.SelectMany(g => g.Points).Should().OnlyContain(p => p.Quality == Core.Polling.ValueQuality.Good);
        _shell.ProjectPath.Should().BeNull("Save must not overwrite the shipped sample");
    }

    [Fact]
    public void ToggleRefreshMode_TriggeredProject_ContinuousThenTriggered()
    {
        _shell.Session.IsContinuous.Should().BeFalse();

        _shell.ToggleRefreshModeCommand.Execute(null);

        _shell.Session.IsContinuous.Should().BeTrue();
        _panel.Session.Mode.Should().Be(Core.Polling.RefreshMode.Continuous);
        _shell.ToggleRefreshModeCommand.Execute(null);
        _shell.StatusLine.Text.Should().Be("Refresh: triggered; F5 refreshes");
    }

    [Fact]
    public async Task ReadOnly_Toggled_EveryWritingCommandDisabled()
    {
        await _panel.ConnectAsync();
        await _shell.RefreshNowCommand.ExecuteAsync(null).Guarded();
        var conveyor = _shell.Outputs.Groups[0].Points[0];
        var speed = _shell.Memory.Cells[0];
        conveyor.SwitchCommand.CanExecute(null).Should().BeTrue();
        speed.BeginEditCommand.CanExecute(null).Should().BeTrue();

        _shell.ToggleReadOnlyCommand.Execute(null);

        _shell.Session.IsReadOnly.Should().BeTrue();
        conveyor.SwitchCommand.CanExecute(null).Should().BeFalse();
        speed.BeginEditCommand.CanExecute(null).Should().BeFalse();
    }

    [Fact]
    public async Task ConnectCommands_FollowTheLine()
    {
        _shell.ConnectCommand.CanExecute(null).Should().BeTrue();
        _shell.RefreshNowCommand.CanExecute(null).Should().BeFalse();

        await _shell.ConnectCommand.ExecuteAsync(null).Guarded();

        _shell.ConnectCommand.CanExecute(null).Should().BeFalse();
        _shell.DisconnectCommand.CanExecute(null).Should().BeTrue();
        _shell.RefreshNowCommand.CanExecute(null).Should().BeTrue();
    }

    [Fact]
    public void Panes_EachCarriesItsViewModel_OneMechanismForTheDockAndTheViewMenu()
    {
        _shell.Panes.Select(p => (p.ContentId, p.Title)).Should().Equal(
            ("Inputs", "Inputs"), ("Outputs", "Outputs"), ("Memory", "Memory"), ("Alarms", "Alarms"), ("Diagnostics", "Diagnostics"), ("Trends", "Trends"));
        _shell.Panes.Select(p => p.Content).Should().Equal(_shell.Inputs, _shell.Outputs, _shell.Memory, _shell.Alarms, _shell.Diagnostics, _shell.Trends);
        _shell.Panes.Where(p => p.IsVisible).Select(p => p.ContentId).Should().Equal("Inputs", "Outputs", "Memory", "Alarms", "Trends");
    }

    [Fact]
    public void Docking_SavedLayoutCannotBeShown_OneLineInTheStatusBarAndTheLog()
    {
        _shell.Docking.ResetAfterFailure("Cannot set Owner property to a Window that has not been shown previously.");

        _shell.StatusLine.Text.Should().Be("The saved window layout could not be shown (Cannot set Owner property to a Window that has not been shown previously.); the default layout is used.");
        _shell.StatusLine.IsError.Should().BeFalse("the panel goes on with the default layout");
        _panel.Log.Messages.Should().Contain(_shell.StatusLine.Text);
        _shell.Docking.Capture().Panes.Should().Equal(_shell.Docking.DefaultLayout.Panes);
    }

    public async ValueTask DisposeAsync()
    {
        await _panel.DisposeAsync();
        Directory.Delete(_folder, recursive: true);
    }

    private async Task MakeDirtyAsync()
    {
        await _panel.ConnectAsync();
        _shell.Memory.NewAddress = "VW100";
        _shell.Memory.NewSymbol = "Count";
        await _shell.Memory.AddCommand.ExecuteAsync(null).Guarded();
        _shell.IsDirty.Should().BeTrue();
    }
}
