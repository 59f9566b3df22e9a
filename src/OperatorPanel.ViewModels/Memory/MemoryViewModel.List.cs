using System.Collections.Immutable;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Memory;

/// <summary>The cell list: add (address checked against the station's CPU), remove, move up and down. Each edit marks the project unsaved.</summary>
public sealed partial class MemoryViewModel
{
    [ObservableProperty]
    public partial ImmutableArray<ProjectStation> StationChoices { get; private set; } = [];

    /// <summary>The station a new cell goes to; the first one unless the operator picks another.</summary>
    [ObservableProperty]
    [NotifyCanExecuteChangedFor(nameof(AddCommand))]
    public partial ProjectStation? NewStation { get; set; }

    public string NewAddress
    {
        get;
        set => SetProperty(ref field, value ?? string.Empty);
    }

    = string.Empty;

    public string NewSymbol
    {
        get;
        set => SetProperty(ref field, value ?? string.Empty);
    }

    = string.Empty;

    /// <summary>Why the new cell was refused ("VW10240: ... CPU 224 has V memory VB0-VB8191"); null when none.</summary>
    [ObservableProperty]
    public partial string? AddError { get; private set; }

    [RelayCommand(CanExecute = nameof(HasNewStation))]
    private async Task AddAsync()
    {
        AddError = null;
        if (NewStation is not { } station)
        {
            return;
        }

        if (!PlcAddress.TryParse(NewAddress, out var address, out var addressError))
        {
            AddError = addressError.Message;
            return;
        }

        var symbol = NewSymbol.Trim();
        // M and V cells are added writable; S, AIW, AQW, T and C are watched where the station's link reads them (PPI),
        // writable where it writes them (S, AQW), and refused with the link's reason on Freeport.
        var link = station.Link.Protocol;
        var monitored = address.Area is MemoryArea.S or MemoryArea.AI or MemoryArea.AQ or MemoryArea.T or MemoryArea.C;
        var writable = LinkAreas.Refusal(address, link, station.Cpu, AddressUse.Write) is null;
        AddError = address.Area is not (MemoryArea.M or MemoryArea.V) && !monitored
            ? $"{address}: the Memory window holds M and V cells (and over PPI S, AIW, AQW, T and C); inputs and outputs have their own windows"
            : LinkAreas.Refusal(address, link, station.Cpu, monitored ? AddressUse.Read : AddressUse.Write)
            ?? (symbol.Length == 0 ? $"{address}: give the cell a symbol"
            : ProjectEdits.SymbolTaken(station, symbol) ? $"{symbol}: {station.Name} already has a symbol of that name" : null);
        if (AddError is not null)
        {
            return;
        }

        var tag = new ProjectTag(symbol, address, DisplayFormats.DefaultFor(address), writable, Description: string.Empty);
        var edited = ProjectEdits.WithTags(_session.Project, station.Address, station.Tags.Add(tag));
        if (await ApplyEditAsync(edited, (station.Address, symbol), message => AddError = message))
        {
            NewAddress = string.Empty;
            NewSymbol = string.Empty;
        }
    }

    [RelayCommand(CanExecute = nameof(HasSelectedCell))]
    private async Task RemoveAsync()
    {
        if (SelectedCell is not { } cell)
        {
            return;
        }

        var tags = cell.Station.Tags;
        var index = tags.IndexOf(cell.Tag);
        var next = index + 1 < tags.Length ? tags[index + 1] : index > 0 ? tags[index - 1] : null;
        var select = next is null ? ((Core.Addressing.Station, string)?)null : (cell.Station.Address, next.Symbol);
        await ApplyEditAsync(ProjectEdits.WithTags(_session.Project, cell.Station.Address, tags.RemoveAt(index)), select, _session.StatusLine.ShowError);
    }

    [RelayCommand(CanExecute = nameof(CanMoveUp))]
    private Task MoveUpAsync() => MoveAsync(-1);

    [RelayCommand(CanExecute = nameof(CanMoveDown))]
    private Task MoveDownAsync() => MoveAsync(+1);

    private bool HasNewStation() => NewStation is not null;

    private bool HasSelectedCell() => SelectedCell is not null;

    private bool CanMoveUp() => CanMove(-1);

    private bool CanMoveDown() => CanMove(+1);

    private bool CanMove(int step) =>
        SelectedCell is { } cell && cell.Station.Tags.IndexOf(cell.Tag) + step is var target && target >= 0 && target < cell.Station.Tags.Length;

    /// <summary>Moves the selected cell within its station's list (cells of different stations never mix).</summary>
    private async Task MoveAsync(int step)
    {
        if (SelectedCell is not { } cell || !CanMove(step))
        {
            return;
        }

        var tags = cell.Station.Tags;
        var index = tags.IndexOf(cell.Tag);
        var moved = tags.RemoveAt(index).Insert(index + step, cell.Tag);
        await ApplyEditAsync(ProjectEdits.WithTags(_session.Project, cell.Station.Address, moved), (cell.Station.Address, cell.Symbol), _session.StatusLine.ShowError);
    }
}
