namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// The main window's place on the desktop, in device-independent pixels: its normal (restored) bounds and whether it was
/// maximised. Saved with the layout, so the panel opens where and as large as the operator left it.
/// </summary>
public readonly record struct WindowPlacement(double Left, double Top, double Width, double Height, bool Maximized)
{
    /// <summary>Smaller than this and the menu and status bar no longer fit; a layout file may carry anything.</summary>
    public const double MinimumWidth = 640;

    public const double MinimumHeight = 400;

    /// <summary>The first start: 1280 x 800, as a shop-floor panel PC's screen, placed by the system.</summary>
    public static WindowPlacement Default => new(double.NaN, double.NaN, 1280, 800, false);

    /// <summary>
    /// The same window, sized at least to the minimum and at most to <paramref name="desktop"/>, and moved fully onto the
    /// desktop: a monitor unplugged since the last run must not leave the window out of reach. A position that is not a
    /// number stays so (the system places the window).
    /// </summary>
    /// <param name="desktop">The virtual screen (all monitors) as left, top, width, height.</param>
    public WindowPlacement FitTo((double Left, double Top, double Width, double Height) desktop)
    {
        var width = Fit(Width, MinimumWidth, desktop.Width, Default.Width);
        var height = Fit(Height, MinimumHeight, desktop.Height, Default.Height);
        var left = double.IsFinite(Left) ? Math.Clamp(Left, desktop.Left, Math.Max(desktop.Left, desktop.Left + desktop.Width - width)) : double.NaN;
        var top = double.IsFinite(Top) ? Math.Clamp(Top, desktop.Top, Math.Max(desktop.Top, desktop.Top + desktop.Height - height)) : double.NaN;
        return new WindowPlacement(left, top, width, height, Maximized);
    }

    private static double Fit(double value, double minimum, double room, double fallback)
    {
        var size = double.IsFinite(value) ? value : fallback;
        return Math.Max(Math.Min(size, room), Math.Min(minimum, room));
    }
}
