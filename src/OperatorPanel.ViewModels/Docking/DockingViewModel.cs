using System.Collections.ObjectModel;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;

namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// The dockable windows (<see cref="DockPaneViewModel"/>, registered by the shell) and their layout: the View menu binds
/// to <see cref="Panes"/>, reset, the main window's place, and the per-user layout file loaded at start and saved at exit.
/// Docking is built with plain WPF in the App (no AvalonDock in the registry copy); this class holds all of its state
/// so it is tested here.
/// </summary>
public sealed partial class DockingViewModel : ObservableObject
{
    private readonly string? _layoutPath;

    /// <param name="layoutPath">The per-user layout file; null keeps the layout for this run only.</param>
    /// <param name="panes">The panes, in View menu order, each with its default place.</param>
    public DockingViewModel(string? layoutPath, IEnumerable<DockPaneViewModel> panes)
    {
        ArgumentNullException.ThrowIfNull(panes);
        _layoutPath = layoutPath;
        Panes = new ReadOnlyCollection<DockPaneViewModel>([.. panes]);
        var duplicate = Panes.GroupBy(p => p.ContentId).FirstOrDefault(g => g.Count() > 1);
        if (duplicate is not null)
        {
            throw new ArgumentException($"two panes have the content id '{duplicate.Key}'", nameof(panes));
        }

        DefaultLayout = new DockLayout([.. Panes.Select(p => p.Default)]);
        Zoom = 1;
        FloatingZoom = 1;
    }

    public IReadOnlyList<DockPaneViewModel> Panes { get; }

    /// <summary>Every pane where it was registered to be (View > Reset window layout).</summary>
    public DockLayout DefaultLayout { get; }

    /// <summary>The main window's place from the saved layout (fit to the desktop by the App); null on the first start.</summary>
    public WindowPlacement? Window { get; set; }

    /// <summary>Why the saved layout was not used or not saved; null when all went well.</summary>
    [ObservableProperty]
    public partial string? Message { get; private set; }

    /// <summary>The whole window's zoom: 1, or with View > Large display the largest that fits (<see cref="FitZoom"/>).</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(ZoomText))]
    public partial double Zoom { get; private set; }

    /// <summary>A floating pane's zoom: 1, or with Large display the full <see cref="DockFit.LargeDisplayZoom"/> (its window is sized by the operator).</summary>
    [ObservableProperty]
    public partial double FloatingZoom { get; private set; }

    /// <summary>For the View menu beside Large display: "1.35x"; empty at 1.</summary>
    public string ZoomText => Zoom > 1 ? $"{Zoom:0.##}x" : string.Empty;

    public DockPaneViewModel this[string contentId] => Panes.First(p => p.ContentId == contentId);

    /// <summary>
    /// Sets <see cref="Zoom"/> for a window client area of <paramref name="width"/> x <paramref name="height"/> DIP whose
    /// menu, banner and status bar take <paramref name="chromeHeight"/> unzoomed: with Large display, the largest zoom up to
    /// 1.6 at which the shown regions keep their minimum sizes (<see cref="DockFit.Zoom"/>); without, 1. Floating panes
    /// take <see cref="FloatingZoom"/>.
    /// </summary>
    public void FitZoom(double width, double height, double chromeHeight, bool largeDisplay)
    {
        Zoom = largeDisplay
            ? DockFit.Zoom(width, height, chromeHeight, (RegionSize(DockPlacement.Left), RegionSize(DockPlacement.Right), RegionSize(DockPlacement.Bottom)))
            : 1;
        FloatingZoom = largeDisplay ? DockFit.LargeDisplayZoom : 1;
    }

    /// <summary>The size the docked panes ask of a side region: the largest of its shown panes; 0 when it has none.</summary>
    public double RegionSize(DockPlacement placement) =>
        Panes.Where(p => p.IsVisible && p.Placement == placement).Select(p => p.DockedSize).DefaultIfEmpty(0).Max();

    /// <summary>Restores the layout saved for this user (default layout and a message when the file is unusable).</summary>
    public void Load()
    {
        if (_layoutPath is null)
        {
            return;
        }

        var layout = DockLayoutStore.Load(_layoutPath, DefaultLayout, out var message);
        Apply(layout);
        Message = message;
    }

    /// <summary>
    /// The saved layout could not be shown (the App failed to place a pane as it says): every pane goes back to the
    /// default layout, the main window keeps its place, and <see cref="Message"/> says so in one line.
    /// </summary>
    public void ResetAfterFailure(string reason)
    {
        ArgumentNullException.ThrowIfNull(reason);
        Apply(DefaultLayout with { Window = Window });
        Message = $"The saved window layout could not be shown ({reason}); the default layout is used.";
    }

    /// <summary>Saves the current layout; a failure is reported in <see cref="Message"/> and the app goes on.</summary>
    public bool Save()
    {
        if (_layoutPath is null || DockLayoutStore.TrySave(Capture(), _layoutPath, out var error))
        {
            return true;
        }

        Message = $"Window layout not saved ({_layoutPath}): {error}";
        return false;
    }

    [RelayCommand]
    private void ResetLayout() => Apply(DefaultLayout with { Window = Window });

    /// <summary>Shows a hidden pane, hides a shown one. Parameter: the pane's <see cref="DockPaneViewModel.ContentId"/>.</summary>
    [RelayCommand]
    private void TogglePane(string contentId) => this[contentId].IsVisible = !this[contentId].IsVisible;

    public DockLayout Capture() => new DockLayout([.. Panes.Select(p => p.Capture())]) { Window = Window };

    public void Apply(DockLayout layout)
    {
        ArgumentNullException.ThrowIfNull(layout);
        var normalized = layout.Normalized(DefaultLayout);
        foreach (var pane in normalized.Panes)
        {
            this[pane.ContentId].Apply(pane);
        }

        Window = normalized.Window;
    }
}
