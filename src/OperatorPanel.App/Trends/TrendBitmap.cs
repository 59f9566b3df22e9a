using System.Windows;
using System.Windows.Media;
using System.Windows.Media.Imaging;
using OperatorPanel.ViewModels.Trends;

namespace OperatorPanel.App.Trends;

/// <summary>A rendered <see cref="TrendPlot"/> copied into a WPF bitmap at the screen's pixel density.</summary>
public static class TrendBitmap
{
    public static BitmapSource Render(TrendPlot plot, Size size, DpiScale dpi)
    {
        var width = Math.Max(200, (int)(size.Width * dpi.DpiScaleX));
        var height = Math.Max(120, (int)(size.Height * dpi.DpiScaleY));
        using var image = TrendChartRenderer.Render(plot, width, height);
        using var pixels = image.PeekPixels();
        var bitmap = new WriteableBitmap(image.Width, image.Height, dpi.PixelsPerInchX, dpi.PixelsPerInchY, PixelFormats.Pbgra32, null);
        bitmap.WritePixels(new Int32Rect(0, 0, image.Width, image.Height), pixels.GetPixels(), pixels.RowBytes * image.Height, pixels.RowBytes);
        bitmap.Freeze();
        return bitmap;
    }
}
