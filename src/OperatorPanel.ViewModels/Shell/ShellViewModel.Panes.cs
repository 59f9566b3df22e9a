using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>
/// The dockable windows (seed 000 §7: Input, Output, Memory, Alarms; plus Diagnostics and Trends). Each is one
/// <see cref="DockPaneViewModel"/> carrying its view model; the App shows it through the DataTemplate for that view
/// model's type (App.xaml), the View menu lists it, and the layout file keys it by content id. Adding a pane is its view
/// model, its DataTemplate and one line here.
/// </summary>
public sealed partial class ShellViewModel
{
    /// <summary>The docking host's and the View menu's panes, in View menu order.</summary>
    public IReadOnlyList<DockPaneViewModel> Panes { get; }

    /// <summary>The panes' layout: the View menu, Large display's zoom, the layout file, the main window's place.</summary>
    public DockingViewModel Docking { get; }

    /// <remarks>
    /// The default layout: Inputs and Outputs at the sides, full height (every point of a CPU 226 fits at 1280x800), Memory
    /// in the centre, Alarms below it, Diagnostics hidden behind Memory, Trends a tab beside Memory.
    /// </remarks>
    private static IReadOnlyList<DockPaneViewModel> RegisterPanes(ShellViewModel shell) =>
    [
        new("Inputs", "Inputs", shell.Inputs, DockPlacement.Left, 210),
        new("Outputs", "Outputs", shell.Outputs, DockPlacement.Right, 260),
        new("Memory", "Memory", shell.Memory, DockPlacement.Center, 300),
        new("Alarms", "Alarms", shell.Alarms, DockPlacement.Bottom, 376),
        new("Diagnostics", "Diagnostics", shell.Diagnostics, DockPlacement.Center, 300, isVisible: false, order: 1),
        new("Trends", "Trends", shell.Trends, DockPlacement.Center, 300, order: 2),
    ];

    /// <summary>The Trends pane redraws from the history every second only while it is shown.</summary>
    private void FollowTrendsPane(DockPaneViewModel pane)
    {
        Trends.IsShown = pane.IsVisible;
        pane.PropertyChanged += (_, e) =>
        {
            if (e.PropertyName == nameof(DockPaneViewModel.IsVisible))
            {
                Trends.IsShown = pane.IsVisible;
            }
        };
    }

    /// <summary>A layout that was not restored, not saved or could not be shown: one line in the status bar and the log.</summary>
    private void OnDockingChanged(object? sender, System.ComponentModel.PropertyChangedEventArgs e)
    {
        if (e.PropertyName == nameof(DockingViewModel.Message) && Docking.Message is { } message)
        {
            _logger.Warning("{Message:l}", message);
            StatusLine.Show(message);
        }
    }
}
