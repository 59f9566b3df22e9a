using System.Collections.Specialized;
using System.ComponentModel;
using System.Windows.Threading;
using OperatorPanel.Core.Polling;
using OperatorPanel.ViewModels.Memory;
using Serilog;

namespace OperatorPanel.App.Services;

/// <summary>
/// Writes one log line when the Memory window first shows a value change from good reads, and again for each project
/// opened. "Connected" and "Polling started" say the link came up; this line says the panel displayed live PLC values,
/// which is what a technician reading the log after a complaint wants to know (installer/wine-smoke.sh waits for it).
/// </summary>
public sealed class LiveValueWitness : IDisposable
{
    private readonly MemoryViewModel _memory;
    private readonly Dispatcher _dispatcher;
    private readonly ILogger _log;
    private readonly Dictionary<MemoryCellViewModel, string> _firstShown = [];
    private readonly List<MemoryCellViewModel> _watched = [];
    private bool _witnessed;

    public LiveValueWitness(MemoryViewModel memory, Dispatcher dispatcher, ILogger log)
    {
        ArgumentNullException.ThrowIfNull(memory);
        ArgumentNullException.ThrowIfNull(dispatcher);
        ArgumentNullException.ThrowIfNull(log);
        (_memory, _dispatcher, _log) = (memory, dispatcher, log);
        _memory.Cells.CollectionChanged += OnCellsChanged;
        WatchAll();
    }

    public void Dispose()
    {
        _memory.Cells.CollectionChanged -= OnCellsChanged;
        UnwatchAll();
    }

    private void OnCellsChanged(object? sender, NotifyCollectionChangedEventArgs e)
    {
        // Cells are rebuilt when a project is opened or edited: start over, so each project's first live value is logged.
        UnwatchAll();
        _firstShown.Clear();
        _witnessed = false;
        WatchAll();
    }

    private void WatchAll()
    {
        foreach (var cell in _memory.Cells)
        {
            cell.PropertyChanged += OnCellChanged;
            _watched.Add(cell);
        }
    }

    private void UnwatchAll()
    {
        foreach (var cell in _watched)
        {
            cell.PropertyChanged -= OnCellChanged;
        }

        _watched.Clear();
    }

    private void OnCellChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (_witnessed || e.PropertyName != nameof(MemoryCellViewModel.ValueText) || sender is not MemoryCellViewModel cell || cell.Quality != ValueQuality.Good)
        {
            return;
        }

        var shown = cell.ValueText;
        if (!_firstShown.TryAdd(cell, shown) && _firstShown[cell] != shown)
        {
            _witnessed = true;
            var first = _firstShown[cell];
            // Written after the dispatcher's layout and render work for the change (ContextIdle): shown, not only received.
            _dispatcher.InvokeAsync(
                () => _log.Information("Live values shown: {Station} {Address} ({Symbol}) went from {First} to {Now}", cell.StationName, cell.Address, cell.Symbol, first, shown),
                DispatcherPriority.ContextIdle);
        }
    }
}
