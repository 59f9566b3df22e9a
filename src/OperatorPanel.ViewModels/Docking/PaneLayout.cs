namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// One pane's saved state. <c>DockedSize</c> is the width (left/right) or height (bottom) while docked, in
/// device-independent pixels; <c>Order</c> the position among the panes sharing a placement (tab order).
/// </summary>
public sealed record PaneLayout(DockPaneId Id, bool IsVisible, DockPlacement Placement, double DockedSize, FloatBounds Float, int Order);
