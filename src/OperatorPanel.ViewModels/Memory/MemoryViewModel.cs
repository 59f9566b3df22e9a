using System.Collections.ObjectModel;
using System.ComponentModel;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Shell;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.ViewModels.Memory;

/// <summary>
/// The Memory window (seed 000 §7, "PLC memory"): the project's memory cells as a table with values, in-place editing
/// confirmed by read-back, and the cell list itself (add, remove, move) edited without leaving the window.
/// </summary>
public sealed partial class MemoryViewModel : PaneViewModel
{
    private readonly PanelSession _session;
    private readonly IDialogService _dialogs;
    private readonly PanelOptions _options;
    private readonly ILogger _logger;
    private MemoryCellViewModel? _selectedCell;
    private (Station Station, string Symbol)? _selectAfterRebuild;

    public MemoryViewModel(PanelSession session, IDialogService dialogs, PanelOptions options, ILogger? logger = null)
        : base("Memory", "memory")
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(dialogs);
        ArgumentNullException.ThrowIfNull(options);
        (_session, _dialogs, _options) = (session, dialogs, options);
        _logger = (logger ?? Logger.None).ForContext<MemoryViewModel>();
        (AddCommand, RemoveCommand, MoveUpCommand, MoveDownCommand) = CreateListCommands();
        session.ProjectChanged += (_, e) =>
        {
            if (e.Kind != ProjectChangeKind.Saved)
            {
                Rebuild();
            }
        };
        session.ValuesChanged += (_, e) => ApplyValues(e);
        session.PropertyChanged += OnSessionChanged;
        Rebuild();
    }

    public ObservableCollection<MemoryCellViewModel> Cells { get; } = [];

    public MemoryCellViewModel? SelectedCell
    {
        get => _selectedCell;
        set
        {
            if (SetProperty(ref _selectedCell, value))
            {
                NotifyListCommands();
            }
        }
    }

    internal bool CanWrite() => _session.IsConnected && !_session.IsReadOnly;

    private void Rebuild()
    {
        var keep = _selectAfterRebuild ?? (SelectedCell is { } selected ? (selected.Station.Address, selected.Symbol) : null);
        _selectAfterRebuild = null;
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
        ApplyValues(new ValuesChangedEventArgs([], reset: true));
    }

    private void ApplyValues(ValuesChangedEventArgs e)
    {
        if (e.Reset)
        {
            foreach (var cell in Cells)
            {
                _session.TryGetValue(cell.Station.Address, cell.PlcAddress, out var value);
                cell.Apply(value);
            }

            return;
        }

        foreach (var change in e.Changes)
        {
            foreach (var cell in Cells.Where(c => c.Station.Address == change.Station && c.PlcAddress == change.Address))
            {
                cell.Apply(change.Current);
            }
        }
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
