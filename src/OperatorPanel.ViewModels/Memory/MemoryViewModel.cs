using System.Collections.ObjectModel;
using System.ComponentModel;
using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.ViewModels.Memory;

/// <summary>
/// The Memory window (seed 000 §7, "PLC memory"): the project's memory cells as a table with values, in-place editing
/// confirmed by read-back, and the cell list itself (add, remove, move) edited without leaving the window.
/// </summary>
public sealed partial class MemoryViewModel : ObservableObject
{
    private readonly PanelSession _session;
    private readonly IDialogService _dialogs;
    private readonly PanelOptions _options;
    private readonly ILogger _logger;
    private readonly List<IDisposable> _subscriptions = [];
    private (Station Station, string Symbol)? _selectAfterRebuild;

    public MemoryViewModel(PanelSession session, IDialogService dialogs, PanelOptions options, ILogger? logger = null)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(dialogs);
        ArgumentNullException.ThrowIfNull(options);
        (_session, _dialogs, _options) = (session, dialogs, options);
        _logger = (logger ?? Logger.None).ForContext<MemoryViewModel>();
        session.ProjectChanged += (_, e) =>
        {
            if (e.Kind != ProjectChangeKind.Saved)
            {
                Rebuild();
            }
        };
        session.PropertyChanged += OnSessionChanged;
        Rebuild();
    }

    public ObservableCollection<MemoryCellViewModel> Cells { get; } = [];

    [ObservableProperty]
    [NotifyCanExecuteChangedFor(nameof(RemoveCommand), nameof(MoveUpCommand), nameof(MoveDownCommand))]
    public partial MemoryCellViewModel? SelectedCell { get; set; }

    internal bool CanWrite() => _session.IsConnected && !_session.IsReadOnly;

    private void Rebuild()
    {
        var keep = _selectAfterRebuild ?? (SelectedCell is { } selected ? (selected.Station.Address, selected.Symbol) : null);
        _selectAfterRebuild = null;
        _subscriptions.ForEach(s => s.Dispose());
        _subscriptions.Clear();
        Cells.Clear();
        foreach (var station in _session.Project.Stations)
        {
            foreach (var tag in station.Tags)
            {
                Cells.Add(new MemoryCellViewModel(station, tag, this));
            }
        }

        SelectedCell = keep is { } key
            ? Cells.FirstOrDefault(c => c.Station.Address == key.Station && c.Symbol.Equals(key.Symbol, StringComparison.OrdinalIgnoreCase))
            : null;
        StationChoices = _session.Project.Stations;
        NewStation = StationChoices.FirstOrDefault(s => s.Address == NewStation?.Address) ?? StationChoices.FirstOrDefault();

        // Each cell hears its own address only: the line routes a change to the cells showing it, no scan of the table.
        _subscriptions.AddRange(Cells.Select(c => _session.Values.Subscribe(c.Station.Address, c.PlcAddress, c.Apply)));
    }

    private void OnSessionChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName is nameof(PanelSession.IsConnected) or nameof(PanelSession.IsReadOnly))
        {
            foreach (var cell in Cells)
            {
                cell.IsEditing &= CanWrite();
                cell.NotifyCommands();
            }
        }
    }

    private async Task<bool> ApplyEditAsync(PanelProject edited, (Station, string)? select, Action<string> refuse)
    {
        var problems = ProjectFile.Check(edited);
        if (!problems.IsEmpty)
        {
            refuse(problems[0].Message);
            return false;
        }

        _selectAfterRebuild = select;
        await _session.EditProjectAsync(edited);
        return true;
    }
}
