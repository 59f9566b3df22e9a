using System.Collections.Immutable;

namespace OperatorPanel.ViewModels.Docking;

/// <summary>The arrangement of every pane; saved per user and restored at start.</summary>
public sealed record DockLayout(ImmutableArray<PaneLayout> Panes)
{
    /// <summary>Smallest docked width/height kept from a layout file.</summary>
    public const double MinimumDockedSize = 80;

    /// <summary>
    /// Inputs and Outputs side by side on the left and right, Memory in the centre with Trends as its second tab, Alarms
    /// below, Diagnostics hidden. The
    /// Alarms pane is tall enough for the sample project's eight alarms (tool bar, header and eight rows of 32 DIP, tab; 376 seen in the panel under Wine);
    /// on a lower window <see cref="DockFit"/> shrinks it and the pending alarms stay on top.
    /// </summary>
    public static DockLayout Default { get; } = new(
    [
        new PaneLayout(DockPaneId.Inputs, true, DockPlacement.Left, 260, FloatBounds.Default, 0),
        new PaneLayout(DockPaneId.Outputs, true, DockPlacement.Right, 260, FloatBounds.Default, 0),
        new PaneLayout(DockPaneId.Memory, true, DockPlacement.Center, 300, FloatBounds.Default, 0),
        new PaneLayout(DockPaneId.Alarms, true, DockPlacement.Bottom, 376, FloatBounds.Default, 0),
        new PaneLayout(DockPaneId.Diagnostics, false, DockPlacement.Center, 300, FloatBounds.Default, 1),
        new PaneLayout(DockPaneId.Trends, true, DockPlacement.Center, 300, FloatBounds.Default, 2),
    ]);

    /// <summary>
    /// Every pane exactly once, with usable sizes: panes missing from a saved layout (an older version) come from
    /// <see cref="Default"/>, duplicates after the first are dropped.
    /// </summary>
    public DockLayout Normalized()
    {
        var panes = new List<PaneLayout>();
        foreach (var id in Enum.GetValues<DockPaneId>())
        {
            var saved = Panes.FirstOrDefault(p => p.Id == id) ?? Default.Panes.First(p => p.Id == id);
            var size = double.IsFinite(saved.DockedSize) ? Math.Max(saved.DockedSize, MinimumDockedSize) : MinimumDockedSize;
            var placement = Enum.IsDefined(saved.Placement) ? saved.Placement : DockPlacement.Center;
            panes.Add(saved with { DockedSize = size, Placement = placement, Float = saved.Float.Normalized() });
        }

        return new DockLayout([.. panes]);
    }
}
