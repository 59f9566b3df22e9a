namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// How the docked regions share the main window, in device-independent pixels of the (zoomed) layout. A docked pane's
/// size is what the user asked for; when the window (or the zoom) leaves less room, the side regions give way before
/// the centre drops below its minimum, each in proportion to its size but never below its own minimum. The Large
/// display zoom is the largest, up to <see cref="LargeDisplayZoom"/>, at which every shown region keeps its minimum.
/// </summary>
public static class DockFit
{
    /// <summary>The zoom of View > Large display when the window has room for it.</summary>
    public const double LargeDisplayZoom = 1.6;

    /// <summary>Between a side region and the centre.</summary>
    public const double SplitterSize = 5;

    /// <summary>Left or right: a lamp, an address and a short symbol on one line.</summary>
    public const double SideMinimum = 200;

    /// <summary>Bottom: the Alarms tool bar, the header and three alarm rows.</summary>
    public const double BottomMinimum = 200;

    /// <summary>Centre: the Memory grid's columns up to the value.</summary>
    public const double CentreMinimumWidth = 420;

    /// <summary>Centre: the Memory tool bar, the header and four cells.</summary>
    public const double CentreMinimumHeight = 260;

    /// <summary>Zoom steps: the layout does not shift for a pixel's change of the window.</summary>
    private const double ZoomStep = 0.05;

    /// <summary>
    /// The sizes of the regions beside (or below) the centre along one axis: <paramref name="preferred"/> (0 for a region
    /// with no pane) when <paramref name="available"/> (the axis's length less the splitters) leaves the centre
    /// <paramref name="centreMinimum"/>; otherwise shrunk in proportion, each to no less than its minimum.
    /// </summary>
    public static double[] Regions(double available, double centreMinimum, double minimum, params double[] preferred)
    {
        ArgumentNullException.ThrowIfNull(preferred);
        var total = preferred.Sum();
        if (total <= 0 || total + centreMinimum <= available)
        {
            return [.. preferred];
        }

        var share = Math.Max(available - centreMinimum, 0) / total;
        return [.. preferred.Select(p => Math.Max(p * share, Math.Min(p, minimum)))];
    }

    /// <summary>
    /// The Large display zoom: the largest step up to <see cref="LargeDisplayZoom"/> at which the shown regions keep
    /// their minimums, never below 1.
    /// </summary>
    /// <param name="width">The window's client area, device-independent pixels.</param>
    /// <param name="height">The window's client area, device-independent pixels.</param>
    /// <param name="chromeHeight">What the menu, alarm banner and status bar take of the height, unzoomed.</param>
    /// <param name="docked">The docked sizes of the shown left, right and bottom regions (0 for one with no pane).</param>
    public static double Zoom(double width, double height, double chromeHeight, (double Left, double Right, double Bottom) docked)
    {
        var needWidth = Need(docked.Left, SideMinimum) + Need(docked.Right, SideMinimum) + CentreMinimumWidth;
        var needHeight = chromeHeight + Need(docked.Bottom, BottomMinimum) + CentreMinimumHeight;
        var fit = Math.Min(width / needWidth, height / needHeight);
        if (!double.IsFinite(fit))
        {
            return 1;
        }

        return Math.Clamp(Math.Floor(fit / ZoomStep + 1e-9) * ZoomStep, 1, LargeDisplayZoom);
    }

    private static double Need(double docked, double minimum) => docked <= 0 ? 0 : Math.Min(docked, minimum) + SplitterSize;
}
