using OperatorPanel.ViewModels.Mvvm;

namespace OperatorPanel.ViewModels.Session;

/// <summary>The operator's settings for this PC (not part of the project); the App persists them per user.</summary>
public sealed class PanelOptions : ObservableObject
{
    private bool _confirmWrites;
    private bool _largeDisplay;

    /// <summary>Ask "Set Q0.3 (Conveyor) to 1?" before every write.</summary>
    public bool ConfirmWrites
    {
        get => _confirmWrites;
        set => SetProperty(ref _confirmWrites, value);
    }

    /// <summary>Panel PCs read from a distance: the App scales fonts and lamps up.</summary>
    public bool LargeDisplay
    {
        get => _largeDisplay;
        set => SetProperty(ref _largeDisplay, value);
    }
}
