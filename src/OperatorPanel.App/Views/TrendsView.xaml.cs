using System.ComponentModel;
using System.Windows;
using System.Windows.Controls;
using System.Windows.Input;
using System.Windows.Media;
using OperatorPanel.App.Trends;
using OperatorPanel.ViewModels.Trends;

namespace OperatorPanel.App.Views;

/// <summary>
/// Visual only: draws the view model's <see cref="TrendPlot"/> into the image at the area's size, and turns the mouse into
/// the view model's fractions of the time axis (wheel: zoom around the pointer, drag: pan, move: cursor).
/// </summary>
public partial class TrendsView : UserControl
{
    private TrendsViewModel? _trends;
    private Point? _dragFrom;

    public TrendsView()
    {
        InitializeComponent();
        DataContextChanged += (_, _) => Attach(DataContext as TrendsViewModel);
        PlotArea.SizeChanged += (_, _) => Draw();
        PlotArea.MouseWheel += OnWheel;
        PlotArea.MouseLeftButtonDown += (_, e) => (_dragFrom, _) = (e.GetPosition(PlotArea), PlotArea.CaptureMouse());
        PlotArea.MouseLeftButtonUp += (_, _) => (_dragFrom, _) = (null, ReleaseCapture());
        PlotArea.MouseMove += OnMove;
        PlotArea.MouseLeave += (_, _) => _trends?.ClearCursorCommand.Execute(null);
    }

    private void Attach(TrendsViewModel? trends)
    {
        if (_trends is not null)
        {
            _trends.PropertyChanged -= OnTrendsChanged;
        }

        _trends = trends;
        if (trends is not null)
        {
            trends.PropertyChanged += OnTrendsChanged;
        }

        Draw();
    }

    private void OnTrendsChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName == nameof(TrendsViewModel.Plot))
        {
            Draw();
        }
    }

    private void Draw()
    {
        if (_trends is null || PlotArea.ActualWidth < 10 || PlotArea.ActualHeight < 10)
        {
            return;
        }

        PlotImage.Source = TrendBitmap.Render(_trends.Plot, new Size(PlotArea.ActualWidth, PlotArea.ActualHeight), VisualTreeHelper.GetDpi(this));
    }

    /// <summary>Where <paramref name="x"/> (device-independent) falls on the time axis, 0 at its start and 1 at its end.</summary>
    private double Fraction(double x)
    {
        var scale = VisualTreeHelper.GetDpi(this).DpiScaleX;
        var left = TrendChartRenderer.LeftMargin / scale;
        var width = PlotArea.ActualWidth - left - (TrendChartRenderer.RightMargin / scale);
        return width <= 0 ? 0 : (x - left) / width;
    }

    private void OnWheel(object sender, MouseWheelEventArgs e)
    {
        _trends?.Zoom(e.Delta > 0 ? 0.8 : 1.25, Math.Clamp(Fraction(e.GetPosition(PlotArea).X), 0, 1));
        e.Handled = true;
    }

    private void OnMove(object sender, MouseEventArgs e)
    {
        var at = e.GetPosition(PlotArea);
        if (_dragFrom is { } from && e.LeftButton == MouseButtonState.Pressed)
        {
            _trends?.Pan(Fraction(from.X) - Fraction(at.X));
            _dragFrom = at;
            return;
        }

        var fraction = Fraction(at.X);
        if (fraction is >= 0 and <= 1)
        {
            _trends?.PointAt(fraction);
        }
    }

    private bool ReleaseCapture()
    {
        PlotArea.ReleaseMouseCapture();
        return true;
    }
}
