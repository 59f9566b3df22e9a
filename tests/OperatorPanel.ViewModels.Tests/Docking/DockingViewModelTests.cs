using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.ViewModels.Tests.Docking;

public sealed class DockingViewModelTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("op-layout-").FullName;

    private string LayoutPath => Path.Combine(_folder, "user", "layout.json");

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public void Load_NoLayoutFile_ShowsTheDefaultLayoutWithoutMessage()
    {
        var docking = new DockingViewModel(LayoutPath);

        docking.Load();

        docking.Message.Should().BeNull();
        docking.Capture().Should().BeEquivalentTo(DockLayout.Default);
        docking.Panes.Select(p => p.AutomationId).Should().Equal("InputsPane", "OutputsPane", "MemoryPane", "AlarmsPane", "DiagnosticsPane");
    }

    [Fact]
    public void SaveThenLoad_MovedFloatedHiddenAndResizedPanes_RestoresThemInANewSession()
    {
        var first = new DockingViewModel(LayoutPath);
        first[DockPaneId.Alarms].FloatCommand.Execute(null);
        first[DockPaneId.Alarms].Float = new FloatBounds(1300, 40, 600, 300);
        first[DockPaneId.Inputs].DockCommand.Execute(DockPlacement.Bottom);
        first[DockPaneId.Inputs].DockedSize = 333;
        first.TogglePaneCommand.Execute(DockPaneId.Outputs);

        first.Save().Should().BeTrue();
        var second = new DockingViewModel(LayoutPath);
        second.Load();

        second.Message.Should().BeNull();
        second[DockPaneId.Alarms].Placement.Should().Be(DockPlacement.Floating);
        second[DockPaneId.Alarms].Float.Should().Be(new FloatBounds(1300, 40, 600, 300));
        second[DockPaneId.Inputs].Placement.Should().Be(DockPlacement.Bottom);
        second[DockPaneId.Inputs].DockedSize.Should().Be(333);
        second[DockPaneId.Outputs].IsVisible.Should().BeFalse();
        second[DockPaneId.Memory].Placement.Should().Be(DockPlacement.Center);
    }

    [Fact]
    public void TogglePane_HiddenPane_IsShownAgain()
    {
        var docking = new DockingViewModel(LayoutPath);
        docking[DockPaneId.Memory].HideCommand.Execute(null);
        docking[DockPaneId.Memory].IsVisible.Should().BeFalse();

        docking.TogglePaneCommand.Execute(DockPaneId.Memory);

        docking[DockPaneId.Memory].IsVisible.Should().BeTrue();
    }

    [Fact]
    public void Load_CorruptLayoutFile_UsesDefaultAndSaysWhichFile()
    {
        Directory.CreateDirectory(Path.GetDirectoryName(LayoutPath)!);
        File.WriteAllText(LayoutPath, "{ not json");
        var docking = new DockingViewModel(LayoutPath);
        docking[DockPaneId.Inputs].IsVisible = false;

        docking.Load();

        docking.Capture().Should().BeEquivalentTo(DockLayout.Default);
        docking.Message.Should().StartWith($"Window layout not restored ({LayoutPath}):").And.EndWith("The default layout is used.");
    }

    [Fact]
    public void Load_LayoutFromOlderVersionWithMissingPaneAndSillySizes_KeepsWhatIsThereAndFillsTheRest()
    {
        Directory.CreateDirectory(Path.GetDirectoryName(LayoutPath)!);
        File.WriteAllText(LayoutPath, """
            [ { "Id": "Inputs", "IsVisible": true, "Placement": "Right", "DockedSize": 5,
                "Float": { "Left": 0, "Top": 0, "Width": 10, "Height": 10 }, "Order": 2 } ]
            """);
        var docking = new DockingViewModel(LayoutPath);

        docking.Load();

        docking.Message.Should().BeNull();
        docking[DockPaneId.Inputs].Placement.Should().Be(DockPlacement.Right);
        docking[DockPaneId.Inputs].DockedSize.Should().Be(DockLayout.MinimumDockedSize);
        docking[DockPaneId.Inputs].Float.Should().Be(new FloatBounds(0, 0, FloatBounds.MinimumSize, FloatBounds.MinimumSize));
        docking[DockPaneId.Alarms].Placement.Should().Be(DockPlacement.Bottom);
    }

    [Fact]
    public void Save_FolderCannotBeCreated_ReportsAndKeepsTheLayout()
    {
        var blocker = Path.Combine(_folder, "file");
        File.WriteAllText(blocker, "x");
        var docking = new DockingViewModel(Path.Combine(blocker, "layout.json"));
        docking[DockPaneId.Alarms].IsVisible = false;

        docking.Save().Should().BeFalse();

        docking.Message.Should().StartWith($"Window layout not saved ({Path.Combine(blocker, "layout.json")}):");
        docking[DockPaneId.Alarms].IsVisible.Should().BeFalse();
    }

    [Fact]
    public void ResetLayout_AfterChanges_RestoresTheDefault()
    {
        var docking = new DockingViewModel(LayoutPath);
        docking[DockPaneId.Outputs].FloatCommand.Execute(null);
        docking[DockPaneId.Alarms].IsVisible = false;

        docking.ResetLayoutCommand.Execute(null);

        docking.Capture().Should().BeEquivalentTo(DockLayout.Default);
    }

    [Fact]
    public void FloatCommand_PaneAlreadyFloating_CannotExecute()
    {
        var pane = new DockingViewModel(LayoutPath)[DockPaneId.Memory];

        pane.FloatCommand.Execute(null);

        pane.IsFloating.Should().BeTrue();
        pane.FloatCommand.CanExecute(null).Should().BeFalse();
        pane.DockCommand.CanExecute(DockPlacement.Left).Should().BeTrue();
    }

    [Fact]
    public void FitZoom_LargeDisplayOffOrOn_IsOneOrWhatTheWindowFits()
    {
        var docking = new DockingViewModel(LayoutPath);

        docking.FitZoom(1272, 773, 92, largeDisplay: false);
        docking.Zoom.Should().Be(1);
        docking.ZoomText.Should().BeEmpty();

        docking.FitZoom(1272, 773, 92, largeDisplay: true);
        docking.Zoom.Should().BeApproximately(1.35, 1e-9);
        docking.ZoomText.Should().Be($"{1.35:0.##}x");

        docking.FitZoom(1920, 1050, 92, largeDisplay: true);
        docking.Zoom.Should().Be(1.6);
    }

    [Fact]
    public void FitZoom_AlarmsPaneHidden_TheLowWindowZoomsFurther()
    {
        var docking = new DockingViewModel(LayoutPath);
        docking[DockPaneId.Alarms].IsVisible = false;

        // Without the bottom region the width decides: 1272 / (205 + 205 + 420) = 1.53.
        docking.FitZoom(1272, 773, 92, largeDisplay: true);

        docking.Zoom.Should().BeApproximately(1.5, 1e-9);
        docking.RegionSize(DockPlacement.Bottom).Should().Be(0);
        docking.RegionSize(DockPlacement.Left).Should().Be(260);
    }
}
