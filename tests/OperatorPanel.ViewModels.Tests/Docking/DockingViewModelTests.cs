using OperatorPanel.ViewModels.Docking;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Docking;

/// <summary>The layout of the shell's registered panes (ShellViewModel.Panes), saved and restored per user.</summary>
public sealed class DockingViewModelTests : IAsyncDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("op-layout-").FullName;
    private readonly PanelFixture _panel = new();

    private string LayoutPath => Path.Combine(_folder, "user", "layout.json");

    public async ValueTask DisposeAsync()
    {
        await _panel.DisposeAsync();
        Directory.Delete(_folder, recursive: true);
    }

    private DockingViewModel Docking(string? path = null) => new(path ?? LayoutPath, _panel.Shell().Panes);

    [Fact]
    public void Load_NoLayoutFile_ShowsTheDefaultLayoutWithoutMessage()
    {
        var docking = Docking();

        docking.Load();

        docking.Message.Should().BeNull();
        docking.Capture().Should().BeEquivalentTo(docking.DefaultLayout);
        docking.Panes.Select(p => p.AutomationId).Should().Equal("InputsPane", "OutputsPane", "MemoryPane", "AlarmsPane", "DiagnosticsPane", "TrendsPane");
    }

    [Fact]
    public void SaveThenLoad_MovedFloatedHiddenAndResizedPanes_RestoresThemInANewSession()
    {
        var first = Docking();
        first["Alarms"].FloatCommand.Execute(null);
        first["Alarms"].Float = new FloatBounds(1300, 40, 600, 300);
        first["Inputs"].DockCommand.Execute(DockPlacement.Bottom);
        first["Inputs"].DockedSize = 333;
        first.TogglePaneCommand.Execute("Outputs");

        first.Save().Should().BeTrue();
        var second = Docking();
        second.Load();

        second.Message.Should().BeNull();
        second["Alarms"].Placement.Should().Be(DockPlacement.Floating);
        second["Alarms"].Float.Should().Be(new FloatBounds(1300, 40, 600, 300));
        second["Inputs"].Placement.Should().Be(DockPlacement.Bottom);
        second["Inputs"].DockedSize.Should().Be(333);
        second["Outputs"].IsVisible.Should().BeFalse();
        second["Memory"].Placement.Should().Be(DockPlacement.Center);
    }

    [Fact]
    public void TogglePane_HiddenPane_IsShownAgain()
    {
        var docking = Docking();
        docking["Memory"].HideCommand.Execute(null);
        docking["Memory"].IsVisible.Should().BeFalse();

        docking.TogglePaneCommand.Execute("Memory");

        docking["Memory"].IsVisible.Should().BeTrue();
    }

    [Fact]
    public void Load_CorruptLayoutFile_UsesDefaultAndSaysWhichFile()
    {
        Directory.CreateDirectory(Path.GetDirectoryName(LayoutPath)!);
        File.WriteAllText(LayoutPath, "{ not json");
        var docking = Docking();
        docking["Inputs"].IsVisible = false;

        docking.Load();

        docking.Capture().Should().BeEquivalentTo(docking.DefaultLayout);
        docking.Message.Should().Be($"Window layout not restored ({LayoutPath}): the file is not a layout this panel wrote (unreadable at line 1, character 3). The default layout is used.");
    }

    [Fact]
    public void Load_LayoutFromOlderVersionWithMissingPaneAndSillySizes_KeepsWhatIsThereAndFillsTheRest()
    {
        Directory.CreateDirectory(Path.GetDirectoryName(LayoutPath)!);
        File.WriteAllText(LayoutPath, """
            [ { "Id": "Inputs", "IsVisible": true, "Placement": "Right", "DockedSize": 5,
                "Float": { "Left": 0, "Top": 0, "Width": 10, "Height": 10 }, "Order": 2 } ]
            """);
        var docking = Docking();

        docking.Load();

        docking.Message.Should().BeNull();
        docking["Inputs"].Placement.Should().Be(DockPlacement.Right);
        docking["Inputs"].DockedSize.Should().Be(DockLayout.MinimumDockedSize);
        docking["Inputs"].Float.Should().Be(new FloatBounds(0, 0, FloatBounds.MinimumSize, FloatBounds.MinimumSize));
        docking["Alarms"].Placement.Should().Be(DockPlacement.Bottom);
    }

    [Fact]
    public void Save_FolderCannotBeCreated_ReportsAndKeepsTheLayout()
    {
        var blocker = Path.Combine(_folder, "file");
        File.WriteAllText(blocker, "x");
        var docking = Docking(Path.Combine(blocker, "layout.json"));
        docking["Alarms"].IsVisible = false;

        docking.Save().Should().BeFalse();

        docking.Message.Should().StartWith($"Window layout not saved ({Path.Combine(blocker, "layout.json")}):");
        docking["Alarms"].IsVisible.Should().BeFalse();
    }

    [Fact]
    public void ResetLayout_AfterChanges_RestoresTheDefault()
    {
        var docking = Docking();
        docking["Outputs"].FloatCommand.Execute(null);
        docking["Alarms"].IsVisible = false;

        docking.ResetLayoutCommand.Execute(null);

        docking.Capture().Should().BeEquivalentTo(docking.DefaultLayout);
    }

    [Fact]
    public void FloatCommand_PaneAlreadyFloating_CannotExecute()
    {
        var pane = Docking()["Memory"];

        pane.FloatCommand.Execute(null);

        pane.IsFloating.Should().BeTrue();
        pane.FloatCommand.CanExecute(null).Should().BeFalse();
        pane.DockCommand.CanExecute(DockPlacement.Left).Should().BeTrue();
    }

    [Fact]
    public void FitZoom_LargeDisplayOffOrOn_IsOneOrWhatTheWindowFits()
    {
        var docking = Docking();

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
        var docking = Docking();
        docking["Alarms"].IsVisible = false;

        // Without the bottom region the width decides: 1272 / (205 + 205 + 420) = 1.53.
        docking.FitZoom(1272, 773, 92, largeDisplay: true);

        docking.Zoom.Should().BeApproximately(1.5, 1e-9);
        docking.RegionSize(DockPlacement.Bottom).Should().Be(0);
        docking.RegionSize(DockPlacement.Left).Should().Be(210);
    }

    [Fact]
    public void SaveThenLoad_FloatingPaneAndMaximisedWindow_RestoresBothAndTheWayBack()
    {
        var first = Docking();
        first["Inputs"].DockCommand.Execute(DockPlacement.Right);
        first["Inputs"].FloatCommand.Execute(null);
        first.Window = new WindowPlacement(40, 30, 1100, 700, Maximized: true);

        first.Save().Should().BeTrue();
        var second = Docking();
        second.Load();

        second.Message.Should().BeNull();
        second.Window.Should().Be(new WindowPlacement(40, 30, 1100, 700, Maximized: true));
        second["Inputs"].IsFloating.Should().BeTrue();
        second["Inputs"].DockBackCommand.Execute(null);
        second["Inputs"].Placement.Should().Be(DockPlacement.Right, "the floating window's Dock button returns the pane where it was docked");
    }

    [Fact]
    public void SaveThenLoad_WindowPlacedByTheSystem_KeepsThePositionUnset()
    {
        var first = Docking();
        first.Window = WindowPlacement.Default;

        first.Save().Should().BeTrue();
        var second = Docking();
        second.Load();

        second.Window!.Value.Left.Should().Be(double.NaN);
        second.Window.Value.Width.Should().Be(1280);
    }

    [Fact]
    public void DockBack_PaneFloatedFromTheDefaultLayout_ReturnsToItsDefaultPlace()
    {
        var docking = Docking();
        var alarms = docking["Alarms"];
        alarms.DockBackCommand.CanExecute(null).Should().BeFalse("a docked pane has nothing to dock back from");

        alarms.FloatCommand.Execute(null);
        alarms.DockBackCommand.CanExecute(null).Should().BeTrue();
        alarms.DockBackCommand.Execute(null);

        alarms.Placement.Should().Be(DockPlacement.Bottom);
    }

    [Fact]
    public void ResetAfterFailure_LayoutTheAppCouldNotShow_DefaultLayoutKeepsTheWindowAndSaysSoInOneLine()
    {
        var docking = Docking();
        docking["Outputs"].FloatCommand.Execute(null);
        docking.Window = new WindowPlacement(0, 0, 900, 600, Maximized: false);

        docking.ResetAfterFailure("Cannot set Owner property to a Window that has not been shown previously.");

        docking.Capture().Should().BeEquivalentTo(docking.DefaultLayout with { Window = new WindowPlacement(0, 0, 900, 600, Maximized: false) });
        docking.Message.Should().Be("The saved window layout could not be shown (Cannot set Owner property to a Window that has not been shown previously.); the default layout is used.");
        docking.Message.Should().NotContain(Environment.NewLine);
    }

    [Fact]
    public void Load_LayoutWithAPaneNoLongerRegistered_DropsItAndKeepsTheOthers()
    {
        Directory.CreateDirectory(Path.GetDirectoryName(LayoutPath)!);
        File.WriteAllText(LayoutPath, """
            { "Window": null, "Panes": [
              { "ContentId": "Gone", "IsVisible": true, "Placement": "Left", "DockedSize": 300, "Float": { "Left": 0, "Top": 0, "Width": 400, "Height": 300 }, "Order": 0 },
              { "ContentId": "Memory", "IsVisible": false, "Placement": "Floating", "DockedSize": 300, "Float": { "Left": 5, "Top": 6, "Width": 400, "Height": 300 }, "Order": 0 } ] }
            """);
        var docking = Docking();

        docking.Load();

        docking.Message.Should().BeNull();
        docking.Panes.Select(p => p.ContentId).Should().Equal("Inputs", "Outputs", "Memory", "Alarms", "Diagnostics", "Trends");
        docking["Memory"].IsVisible.Should().BeFalse();
        docking["Memory"].Float.Should().Be(new FloatBounds(5, 6, 400, 300));
        docking["Memory"].Docked.Should().Be(DockPlacement.Center, "an older file does not say where it was docked: its default place");
    }

    [Fact]
    public void FitZoom_LargeDisplay_FloatingPanesTakeTheFullZoom()
    {
        var docking = Docking();

        docking.FitZoom(1272, 773, 92, largeDisplay: true);
        docking.FloatingZoom.Should().Be(DockFit.LargeDisplayZoom, "a floating pane's window is sized by the operator, not shared with the others");

        docking.FitZoom(1272, 773, 92, largeDisplay: false);
        docking.FloatingZoom.Should().Be(1);
    }

    [Fact]
    public void Constructor_TwoPanesWithOneContentId_IsRefused()
    {
        var create = () => new DockingViewModel(LayoutPath, [new("A", "A", new object(), DockPlacement.Left, 100), new("A", "B", new object(), DockPlacement.Right, 100)]);

        create.Should().Throw<ArgumentException>().WithMessage("two panes have the content id 'A'*");
    }
}
