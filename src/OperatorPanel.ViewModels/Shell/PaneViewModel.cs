using CommunityToolkit.Mvvm.ComponentModel;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>
/// A dockable window (Inputs, Outputs, Memory, Alarms, Diagnostics): <see cref="ContentId"/> keys the saved layout,
/// <see cref="IsVisible"/> is what the View menu toggles (the AvalonDock MVVM pattern of the house style).
/// </summary>
public abstract partial class PaneViewModel(string title, string contentId) : ObservableObject
{
    public string Title { get; } = title;

    public string ContentId { get; } = contentId;

    [ObservableProperty]
    public partial bool IsVisible { get; set; } = true;
}
