using CommunityToolkit.Mvvm.ComponentModel;

namespace OperatorPanel.ViewModels.Session;

/// <summary>The operator's settings for this PC (not part of the project); the App persists them per user.</summary>
public sealed partial class PanelOptions : ObservableObject
{
    /// <summary>
    /// Ask "Set Q0.3 (Conveyor) from 0 to 1?" before every write. On unless the operator turns it off (Line > Confirm
    /// writes): one click must not switch an output of a running line.
    /// </summary>
    [ObservableProperty]
    public partial bool ConfirmWrites { get; set; } = true;

    /// <summary>Panel PCs read from a distance: the App scales fonts and lamps up.</summary>
    [ObservableProperty]
    public partial bool LargeDisplay { get; set; }
}
