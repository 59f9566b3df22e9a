using OperatorPanel.Historian.Reading;
using OperatorPanel.ViewModels.Trends;
using ScottPlot;
using SkiaSharp;

namespace OperatorPanel.App.Trends;

/// <summary>
/// Draws a <see cref="TrendPlot"/> with ScottPlot 5 onto a SkiaSharp surface: one lane per tag, stacked, sharing the time
/// axis (local time at the bottom), each with its own value axis in the tag's units; known stretches as step lines, gaps
/// shaded (grey: not recorded, orange: stale, red: bad), the cursor as a vertical line. Every lane has the same margins,
/// so the time axis lines up and the view can turn a mouse position into a fraction of the window.
/// </summary>
public static class TrendChartRenderer
{
    /// <summary>Pixels of each lane left of its data area (the value axis and the tag's name), and right of it.</summary>
    public const int LeftMargin = 110;
    public const int RightMargin = 16;
    private const int TimeAxisHeight = 44;
    private const int LaneGap = 6;

    /// <summary>Renders into a BGRA surface of <paramref name="width"/> x <paramref name="height"/> pixels; the caller copies its pixels.</summary>
    public static SKImage Render(TrendPlot plot, int width, int height)
    {
        ArgumentNullException.ThrowIfNull(plot);
        var info = new SKImageInfo(Math.Max(width, 200), Math.Max(height, 120), SKColorType.Bgra8888, SKAlphaType.Premul);
        using var surface = SKSurface.Create(info);
        surface.Canvas.Clear(SKColors.White);
        var lanes = plot.Lanes.Count == 0 ? [null] : plot.Lanes.Cast<TrendLane?>().ToList();
        var laneHeight = (info.Height - TimeAxisHeight) / lanes.Count;
        for (var i = 0; i < lanes.Count; i++)
        {
            // Each lane on a surface of its own: a plot fills its whole canvas with its background when it renders.
            var last = i == lanes.Count - 1;
            var top = i * laneHeight;
            var rows = last ? info.Height - top : laneHeight;
            using var lanePlot = Lane(plot, lanes[i], last);
            using var laneSurface = SKSurface.Create(new SKImageInfo(info.Width, rows, SKColorType.Bgra8888, SKAlphaType.Premul));
            lanePlot.Render(laneSurface);
            using var image = laneSurface.Snapshot();
            surface.Canvas.DrawImage(image, 0, top);
        }

        return surface.Snapshot();
    }

    private static Plot Lane(TrendPlot plot, TrendLane? lane, bool showTime)
    {
        var p = new Plot();
        p.Layout.Fixed(new PixelPadding(LeftMargin, RightMargin, showTime ? TimeAxisHeight : LaneGap, LaneGap));
        var (from, to) = (X(plot.From), X(plot.To));
        var ticks = p.Axes.DateTimeTicksBottom();
        ((ScottPlot.TickGenerators.DateTimeAutomatic)ticks.TickGenerator).LabelFormatter = at => at.ToString(
            plot.To - plot.From > TimeSpan.FromDays(1) ? "MM-dd HH:mm" : plot.To - plot.From > TimeSpan.FromMinutes(10) ? "HH:mm" : "HH:mm:ss",
            System.Globalization.CultureInfo.InvariantCulture);
        p.Axes.SetLimitsX(from, to);
        p.Axes.Bottom.TickLabelStyle.IsVisible = showTime;
        p.Grid.MajorLineColor = Colors.Black.WithAlpha(0.08);
        if (lane is null)
        {
            p.Axes.SetLimitsY(0, 1);
            return p;
        }

        foreach (var gap in lane.Gaps)
        {
            var span = p.Add.HorizontalSpan(X(gap.From), X(gap.To));
            span.FillStyle.Color = gap.Kind switch
            {
                TrendGapKind.NotRecorded => Colors.Gray.WithAlpha(0.15),
                TrendGapKind.Stale => Colors.Orange.WithAlpha(0.25),
                TrendGapKind.Bad => Colors.Red.WithAlpha(0.2),
            };
            span.LineStyle.Width = 0;
        }

        var color = Color.FromARGB(lane.Color);
        foreach (var segment in lane.Segments)
        {
            var line = p.Add.Scatter(segment.Points.Select(pt => X(pt.At)).ToArray(), segment.Points.Select(pt => pt.Value).ToArray());
            line.ConnectStyle = ConnectStyle.StepHorizontal;
            line.MarkerSize = 0;
            line.LineWidth = 2;
            line.Color = color;
        }

        if (plot.Cursor is { } cursor)
        {
            var marker = p.Add.VerticalLine(X(cursor));
            marker.Color = Colors.Black.WithAlpha(0.6);
            marker.LineWidth = 1;
        }

        var (min, max) = lane.IsBit ? (0.0, 1.0) : (lane.Min, lane.Max);
        var pad = lane.IsBit ? 0.25 : Math.Max((max - min) * 0.1, Math.Max(Math.Abs(max) * 0.01, 0.5));
        p.Axes.SetLimitsY(min - pad, max + pad);
        if (lane.IsBit)
        {
            p.Axes.Left.SetTicks([0, 1], ["0", "1"]);
        }

        p.Axes.Left.Label.Text = lane.Name;
        p.Axes.Left.Label.ForeColor = color;
        p.Axes.Left.Label.FontSize = 12;
        return p;
    }

    /// <summary>ScottPlot's time axis counts OLE automation days of local time.</summary>
    private static double X(DateTimeOffset at) => TimeZoneInfo.ConvertTime(at, TimeZoneInfo.Local).DateTime.ToOADate();
}
