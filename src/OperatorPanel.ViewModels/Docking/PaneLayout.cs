namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// One pane's saved state, keyed by its <see cref="DockPaneViewModel.ContentId"/>. <c>DockedSize</c> is the width
/// (left/right) or height (bottom) while docked, in device-independent pixels; <c>Order</c> the position among the panes
/// sharing a placement (tab order); <c>Docked</c> where the pane docks back to from floating (null in older files: its
/// default place).
/// </summary>
public sealed record PaneLayout(string ContentId, bool IsVisible, DockPlacement Placement, double DockedSize, FloatBounds Float, int Order)
{
    public DockPlacement? Docked { get; init; }
}
