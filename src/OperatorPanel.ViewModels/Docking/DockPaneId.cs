namespace OperatorPanel.ViewModels.Docking;

/// <summary>The panel's dockable windows (seed 000, section 7: Input, Output, Memory, Alarms; plus Diagnostics and Trends).</summary>
public enum DockPaneId
{
    Inputs,
    Outputs,
    Memory,
    Alarms,
    Diagnostics,
    Trends,
}
