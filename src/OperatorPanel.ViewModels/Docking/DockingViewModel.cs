using System.Collections.ObjectModel;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;

namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// The four (five) dockable windows and their layout: View menu toggles, reset, and the per-user layout file loaded
/// at start and saved at exit. Docking is built with plain WPF in the App (no AvalonDock in the registry copy); this
/// class holds all of its state so it is tested here.
/// </summary>
public sealed partial class DockingViewModel : ObservableObject
{
    private readonly string _layoutPath;

    public DockingViewModel(string layoutPath)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(layoutPath);
        _layoutPath = layoutPath;
        Panes = new ReadOnlyCollection<DockPaneViewModel>(
            [.. DockLayout.Default.Panes.Select(p => new DockPaneViewModel(p, TitleOf(p.Id), $"{p.Id}Pane"))]);
        Zoom = 1;
    }

    public IReadOnlyList<DockPaneViewModel> Panes { get; }

    /// <summary>Why the saved layout was not used or not saved; null when all went well.</summary>
    [ObservableProperty]
    public partial string? Message { get; private set; }

    /// <summary>The whole window's zoom: 1, or with View > Large display the largest that fits (<see cref="FitZoom"/>).</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(ZoomText))]
    public partial double Zoom { get; private set; }

    /// <summary>For the View menu beside Large display: "1.35x"; empty at 1.</summary>
    public string ZoomText => Zoom > 1 ? $"{Zoom:0.##}x" : string.Empty;

    public DockPaneViewModel this[DockPaneId id] => Panes.First(p => p.Id == id);

    /// <summary>
    /// Sets <see cref="Zoom"/> for a window client area of <paramref name="width"/> x <paramref name="height"/> DIP whose
    /// menu, banner and status bar take <paramref name="chromeHeight"/> unzoomed: with Large display, the largest zoom up to
    /// 1.6 at which the shown regions keep their minimum sizes (<see cref="DockFit.Zoom"/>); without, 1.
    /// </summary>
    public void FitZoom(double width, double height, double chromeHeight, bool largeDisplay) =>
        Zoom = largeDisplay
            ? DockFit.Zoom(width, height, chromeHeight, (RegionSize(DockPlacement.Left), RegionSize(DockPlacement.Right), RegionSize(DockPlacement.Bottom)))
            : 1;

    /// <summary>The size the docked panes ask of a side region: the largest of its shown panes; 0 when it has none.</summary>
    public double RegionSize(DockPlacement placement) =>
        Panes.Where(p => p.IsVisible && p.Placement == placement).Select(p => p.DockedSize).DefaultIfEmpty(0).Max();

    public static string TitleOf(DockPaneId id) => id switch
    {
        DockPaneId.Inputs => "Inputs",
        DockPaneId.Outputs => "Outputs",
        DockPaneId.Memory => "Memory",
        DockPaneId.Alarms => "Alarms",
        DockPaneId.Diagnostics => "Diagnostics",
        DockPaneId.Trends => "Trends",
    };

    /// <summary>Restores the layout saved for this user (default layout and a message when the file is unusable).</summary>
    public void Load()
    {
        var layout = DockLayoutStore.Load(_layoutPath, out var message);
        Apply(layout);
        Message = message;
    }

    /// <summary>Saves the current layout; a failure is reported in <see cref="Message"/> and the app goes on.</summary>
    public bool Save()
    {
        if (DockLayoutStore.TrySave(Capture(), _layoutPath, out var error))
        {
            return true;
        }

        Message = $"Window layout not saved ({_layoutPath}): {error}";
        return false;
    }

    [RelayCommand]
    private void ResetLayout() => Apply(DockLayout.Default);

    /// <summary>View menu (TogglePaneCommand): shows a hidden pane, hides a shown one. Parameter: the <see cref="DockPaneId"/>.</summary>
    [RelayCommand]
    private void TogglePane(DockPaneId id) => this[id].IsVisible = !this[id].IsVisible;

    public DockLayout Capture() => new([.. Panes.Select(p => p.Capture())]);

    public void Apply(DockLayout layout)
    {
        ArgumentNullException.ThrowIfNull(layout);
        foreach (var pane in layout.Normalized().Panes)
        {
            this[pane.Id].Apply(pane);
        }
    }
}
