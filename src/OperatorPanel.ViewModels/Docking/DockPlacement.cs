namespace OperatorPanel.ViewModels.Docking;

/// <summary>Where a pane sits: docked to a side of the main window, in its centre area (tabbed), or in a window of its own.</summary>
public enum DockPlacement
{
    Left,
    Right,
    Bottom,
    Center,
    Floating,
}
