using System.Collections.Immutable;

namespace OperatorPanel.ViewModels.Docking;

/// <summary>The arrangement of every pane and the main window's place; saved per user and restored at start.</summary>
public sealed record DockLayout(ImmutableArray<PaneLayout> Panes)
{
    /// <summary>Smallest docked width/height kept from a layout file.</summary>
    public const double MinimumDockedSize = 80;

    /// <summary>The main window's place when the layout was saved; null in a layout that has none (older files).</summary>
    public WindowPlacement? Window { get; init; }

    /// <summary>
    /// Every pane of <paramref name="defaults"/> exactly once, in its order, with usable sizes: panes missing from a saved
    /// layout (an older version, or a pane added since) come from <paramref name="defaults"/>, unknown ones (a pane
    /// removed since) and duplicates after the first are dropped.
    /// </summary>
    public DockLayout Normalized(DockLayout defaults)
    {
        ArgumentNullException.ThrowIfNull(defaults);
        var panes = new List<PaneLayout>();
        foreach (var fallback in defaults.Panes)
        {
            var saved = Panes.FirstOrDefault(p => p.ContentId == fallback.ContentId) ?? fallback;
            var size = double.IsFinite(saved.DockedSize) ? Math.Max(saved.DockedSize, MinimumDockedSize) : MinimumDockedSize;
            var placement = Enum.IsDefined(saved.Placement) ? saved.Placement : fallback.Placement;
            var docked = saved.Docked is { } d && Enum.IsDefined(d) && d != DockPlacement.Floating ? d : fallback.Docked;
            panes.Add(saved with { DockedSize = size, Placement = placement, Float = saved.Float.Normalized(), Docked = docked });
        }

        return new DockLayout([.. panes]) { Window = Window };
    }
}
