using System.ComponentModel;
using System.Windows.Threading;
using OperatorPanel.ViewModels.Trends;
using Serilog;

namespace OperatorPanel.App.Services;

/// <summary>
/// Writes one log line when the Trends window first draws a live trend with values in it, after the dispatcher has
/// rendered it: what a technician reading the log wants to know, and what installer/wine-smoke.sh waits for before its
/// screenshot of the Trends window.
/// </summary>
public sealed class TrendWitness : IDisposable
{
    private readonly TrendsViewModel _trends;
    private readonly Dispatcher _dispatcher;
    private readonly ILogger _log;
    private bool _witnessed;

    public TrendWitness(TrendsViewModel trends, Dispatcher dispatcher, ILogger log)
    {
        ArgumentNullException.ThrowIfNull(trends);
        (_trends, _dispatcher, _log) = (trends, dispatcher, log);
        trends.PropertyChanged += OnChanged;
    }

    public void Dispose() => _trends.PropertyChanged -= OnChanged;

    private void OnChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (_witnessed || e.PropertyName != nameof(TrendsViewModel.Plot) || !_trends.IsShown)
        {
            return;
        }

        var plot = _trends.Plot;
        var points = plot.Lanes.Sum(l => l.Segments.Sum(s => s.Points.Count));
        if (!plot.IsLive || points < 2 * Math.Max(1, plot.Lanes.Count))
        {
            return;
        }

        _witnessed = true;
        _dispatcher.InvokeAsync(
            () => _log.Information("Trend drawn: {Lanes} live lanes ({Names}), {Points} points", plot.Lanes.Count, string.Join(", ", plot.Lanes.Select(l => l.Name)), points),
            DispatcherPriority.ContextIdle);
    }
}
