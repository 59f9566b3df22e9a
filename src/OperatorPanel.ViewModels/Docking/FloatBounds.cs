namespace OperatorPanel.ViewModels.Docking;

/// <summary>A floating pane's window position and size in device-independent pixels.</summary>
public readonly record struct FloatBounds(double Left, double Top, double Width, double Height)
{
    public static FloatBounds Default => new(120, 120, 480, 360);

    /// <summary>Sizes below this would make a pane impossible to grab again.</summary>
    public const double MinimumSize = 120;

    /// <summary>The same window clamped to a usable size (a layout file may carry anything).</summary>
    public FloatBounds Normalized() => new(
        double.IsFinite(Left) ? Left : Default.Left,
        double.IsFinite(Top) ? Top : Default.Top,
        double.IsFinite(Width) ? Math.Max(Width, MinimumSize) : Default.Width,
        double.IsFinite(Height) ? Math.Max(Height, MinimumSize) : Default.Height);
}
