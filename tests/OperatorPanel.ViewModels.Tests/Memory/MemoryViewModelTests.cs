using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.ViewModels.Memory;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Memory;

public sealed class MemoryViewModelTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new();
    private readonly MemoryViewModel _memory;
    private readonly List<ProjectChangeKind> _changes = [];

    public MemoryViewModelTests()
    {
        _memory = new MemoryViewModel(_panel.Session, _panel.Dialogs, _panel.Options, _panel.Logger);
        _panel.Session.ProjectChanged += (_, e) => _changes.Add(e.Kind);
    }

    private MemoryCellViewModel Speed => _memory.Cells.Single(c => c.Symbol == "Speed");

    [Fact]
    public async Task Commit_ValueOutOfRangeForSignedWord_RefusedWithMessageAndNothingWritten()
    {
        await ConnectAndRefreshAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 1234);
        var frames = _panel.Transport.FramesSent;
        Speed.BeginEditCommand.Execute(null);
        Speed.EditText = "70000";

        await Speed.CommitEditCommand.ExecuteAsync(null).Guarded();

        Speed.EditError.Should().Be("VW10: 70000 is outside -32768..32767, the range of a signed word");
        Speed.IsEditing.Should().BeTrue("the operator corrects the value or presses Esc");
        _panel.Session.StatusLine.Text.Should().Be(Speed.EditError);
        _panel.Transport.FramesSent.Should().Be(frames, "nothing was sent");
        _panel.Plc.Memory.ReadWord(ProtocolArea.V, 10).Should().Be(1234);
    }

    [Fact]
    public async Task Commit_ValidValue_WrittenAndShownOnlyAfterReadBack()
    {
        await ConnectAndRefreshAsync();
        Speed.BeginEditCommand.Execute(null);
        Speed.EditText = "-1500";

        await Speed.CommitEditCommand.ExecuteAsync(null).Guarded();

        _panel.Plc.Memory.ReadWord(ProtocolArea.V, 10).Should().Be(unchecked((ushort)-1500));
        Speed.ValueText.Should().Be("-1500");
        Speed.IsEditing.Should().BeFalse();
        Speed.WriteError.Should().BeNull();
        _panel.Session.StatusLine.Text.Should().Be("VW10 (Speed): -1500 written and confirmed by the PLC");
    }

    [Fact]
    public async Task Commit_ConfirmWritesOn_AsksWithTheOldAndTheNewValue()
    {
        _panel.Options.ConfirmWrites = true;
        await _panel.ConnectAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 1234);
        await _panel.RefreshAsync();
        Speed.BeginEditCommand.Execute(null);
        Speed.EditText = "1500";
        _panel.Dialogs.ConfirmAnswers.Enqueue(true);

        await Speed.CommitEditCommand.ExecuteAsync(null).Guarded();

        _panel.Dialogs.Questions.Should().Equal("Set VW10 (Speed) from 1234 to 1500?");
        _panel.Plc.Memory.ReadWord(ProtocolArea.V, 10).Should().Be(1500);
    }

    [Fact]
    public async Task Commit_ConfirmWritesOnNothingReadYet_TheQuestionSaysSo()
    {
        _panel.Options.ConfirmWrites = true;
        await _panel.ConnectAsync();
        Speed.BeginEditCommand.Execute(null);
        Speed.EditText = "7";
        _panel.Dialogs.ConfirmAnswers.Enqueue(false);

        await Speed.CommitEditCommand.ExecuteAsync(null).Guarded();

        _panel.Dialogs.Questions.Should().Equal("Set VW10 (Speed) from not read yet to 7?");
    }

    [Fact]
    public async Task CancelEdit_Escape_NothingWrittenEditorClosed()
    {
        await ConnectAndRefreshAsync();
        var frames = _panel.Transport.FramesSent;
        Speed.BeginEditCommand.Execute(null);
        Speed.EditText = "12";

        Speed.CancelEditCommand.Execute(null);

        Speed.IsEditing.Should().BeFalse();
        Speed.CommitEditCommand.CanExecute(null).Should().BeFalse();
        _panel.Transport.FramesSent.Should().Be(frames);
    }

    [Fact]
    public void Format_IsTheProjectsSetting_ShownWithUnitAndScaleAndNotChangeableHere()
    {
        Speed.FormatText.Should().Be("signed");
        Speed.WidthText.Should().Be("word");
        typeof(MemoryCellViewModel).GetProperty(nameof(MemoryCellViewModel.Format))!.CanWrite.Should().BeFalse("the operator does not change a cell's format in the live view");
        typeof(MemoryCellViewModel).GetProperty("FormatChoices").Should().BeNull();
    }

    [Fact]
    public async Task AddCell_ValidAddress_AddedPolledAndProjectEdited()
    {
        await ConnectAndRefreshAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 100, 42);
        _memory.NewAddress = "vw100";
        _memory.NewSymbol = "Count";

        await _memory.AddCommand.ExecuteAsync(null).Guarded();
        await _panel.RefreshAsync();

        _memory.AddError.Should().BeNull();
        _memory.Cells.Select(c => c.Address).Should().Equal("VW10", "MB4", "VD20", "VW100");
        _memory.SelectedCell!.Symbol.Should().Be("Count");
        _memory.SelectedCell.ValueText.Should().Be("42");
        _panel.Session.Project.Stations[0].Tags[^1].Address.Should().Be(PlcAddress.Parse("VW100"));
        _changes.Should().Equal(ProjectChangeKind.Edited);
        _memory.NewAddress.Should().BeEmpty();
    }

    [Theory]
    [InlineData("VW8191", "Late", "VW8191")]
    [InlineData("QB0", "Out", "QB0: the Memory window holds M and V cells (and over PPI S, AIW, AQW, T and C); inputs and outputs have their own windows")]
    [InlineData("AIW0", "Level", "AIW0: the Freeport link reads only I, Q, M and V: its handler reaches memory through pointers")]
    [InlineData("T37", "Timer", "T37: the Freeport link reads only I, Q, M and V: its handler leaves timers out to stay small")]
    [InlineData("VW12", "speed", "speed: Filler already has a symbol of that name")]
    [InlineData("VW12", " ", "VW12: give the cell a symbol")]
    public async Task AddCell_Refused_MessageAndProjectUnchanged(string address, string symbol, string expectedStart)
    {
        var before = _panel.Session.Project;
        _memory.NewAddress = address;
        _memory.NewSymbol = symbol;

        await _memory.AddCommand.ExecuteAsync(null).Guarded();

        _memory.AddError.Should().StartWith(expectedStart);
        _panel.Session.Project.Should().BeSameAs(before);
        _changes.Should().BeEmpty();
    }

    [Fact]
    public async Task RemoveAndMove_SelectedCell_ListAndProjectFollow()
    {
        _memory.SelectedCell = _memory.Cells.Single(c => c.Symbol == "Temperature");
        _memory.MoveDownCommand.CanExecute(null).Should().BeFalse("it is last");

        await _memory.MoveUpCommand.ExecuteAsync(null).Guarded();
        await _memory.MoveUpCommand.ExecuteAsync(null).Guarded();

        _memory.Cells.Select(c => c.Symbol).Should().Equal("Temperature", "Speed", "Recipe");
        _memory.SelectedCell!.Symbol.Should().Be("Temperature");
        _memory.MoveUpCommand.CanExecute(null).Should().BeFalse("it is first");

        _memory.SelectedCell = _memory.Cells.Single(c => c.Symbol == "Speed");
        await _memory.RemoveCommand.ExecuteAsync(null).Guarded();

        _memory.Cells.Select(c => c.Symbol).Should().Equal("Temperature", "Recipe");
        _memory.SelectedCell!.Symbol.Should().Be("Recipe");
        _panel.Session.Project.Stations[0].Tags.Select(t => t.Symbol).Should().Equal("Temperature", "Recipe");
        _changes.Should().Equal(ProjectChangeKind.Edited, ProjectChangeKind.Edited, ProjectChangeKind.Edited);
    }

    [Fact]
    public async Task RemoveCell_Connected_EngineStopsWatchingIt()
    {
        await ConnectAndRefreshAsync();
        _memory.SelectedCell = Speed;

        await _memory.RemoveCommand.ExecuteAsync(null).Guarded();
        await _panel.RefreshAsync();

        _panel.Session.Values.TryGetValue(PanelFixture.Filler, PlcAddress.Parse("VW10"), out _).Should().BeFalse();
        _panel.Session.Values.TryGetValue(PanelFixture.Filler, PlcAddress.Parse("MB4"), out var recipe).Should().BeTrue();
        recipe.Quality.Should().Be(Core.Polling.ValueQuality.Good, string.Join("\n", _panel.Log.Events.Select(e => e.RenderMessage(null) + " " + e.Exception)));
    }

    public async ValueTask DisposeAsync() => await _panel.DisposeAsync();

    private async Task ConnectAndRefreshAsync()
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();
    }
}
