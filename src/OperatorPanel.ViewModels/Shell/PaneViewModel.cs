using OperatorPanel.ViewModels.Mvvm;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>
/// A dockable window (Inputs, Outputs, Memory, Alarms, Diagnostics): <see cref="ContentId"/> keys the saved layout,
/// <see cref="IsVisible"/> is what the View menu toggles (the AvalonDock MVVM pattern of the house style).
/// </summary>
public abstract class PaneViewModel(string title, string contentId) : ObservableObject
{
    private bool _isVisible = true;

    public string Title { get; } = title;

    public string ContentId { get; } = contentId;

    public bool IsVisible
    {
        get => _isVisible;
        set => SetProperty(ref _isVisible, value);
    }
}
