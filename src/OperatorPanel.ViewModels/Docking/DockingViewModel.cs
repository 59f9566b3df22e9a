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
    }

    public IReadOnlyList<DockPaneViewModel> Panes { get; }

    /// <summary>Why the saved layout was not used or not saved; null when all went well.</summary>
    [ObservableProperty]
    public partial string? Message { get; private set; }

    public DockPaneViewModel this[DockPaneId id] => Panes.First(p => p.Id == id);

    public static string TitleOf(DockPaneId id) => id switch
    {
        DockPaneId.Inputs => "Inputs",
        DockPaneId.Outputs => "Outputs",
        DockPaneId.Memory => "Memory",
        DockPaneId.Alarms => "Alarms",
        DockPaneId.Diagnostics => "Diagnostics",
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
