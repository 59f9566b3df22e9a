using System.Collections.Immutable;
using System.Collections.ObjectModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// Step 3: the memory cells the PLC memory window watches (seed 000 §7: any bit, byte, word or double word of M and V;
/// I and Q as the project file allows; on a PPI link (step 5) also SM, S, AIW, AQW, T and C). Each address is checked
/// against the link and the CPU, for writing when writable.
/// </summary>
public sealed partial class MemoryCellsStepViewModel : WizardStepViewModel
{
    internal MemoryCellsStepViewModel(IEnumerable<ProjectTag> tags)
    {
        Cells = new ObservableCollection<MemoryCellRowViewModel>(tags.Select(t => new MemoryCellRowViewModel(t)));
        Track(Cells);
    }

    public override int Number => 3;

    public override string Title => "Memory cells";

    public ObservableCollection<MemoryCellRowViewModel> Cells { get; }

    [RelayCommand]
    private void Add() => Cells.Add(new MemoryCellRowViewModel());

    [RelayCommand]
    private void Remove(MemoryCellRowViewModel? row)
    {
        if (row is not null)
        {
            Cells.Remove(row);
        }
    }

    [RelayCommand(CanExecute = nameof(CanMoveUp))]
    private void MoveUp(MemoryCellRowViewModel? row) => Cells.Move(IndexOf(row), IndexOf(row) - 1);

    [RelayCommand(CanExecute = nameof(CanMoveDown))]
    private void MoveDown(MemoryCellRowViewModel? row) => Cells.Move(IndexOf(row), IndexOf(row) + 1);

    private bool CanMoveUp(MemoryCellRowViewModel? row) => IndexOf(row) > 0;

    private bool CanMoveDown(MemoryCellRowViewModel? row) => IndexOf(row) is var i && i >= 0 && i < Cells.Count - 1;

    private int IndexOf(MemoryCellRowViewModel? row) => row is null ? -1 : Cells.IndexOf(row);

    internal ImmutableArray<ProjectTag> Build() => [.. Cells.Select(r => Tag(r, PlcAddress.Parse(r.Address.Trim()), out _)!)];

    /// <summary>The row's tag with unit, scale and range; null with the reason when one of them is not written right.</summary>
    private static ProjectTag? Tag(MemoryCellRowViewModel row, PlcAddress address, out string? error)
    {
        var tag = new ProjectTag(row.Symbol.Trim(), address, row.Format, row.Writable, row.Description.Trim());
        if (!TagScale.TryParse(row.Scale, out var scale, out error) || !TagRange.TryParse(row.Range, out var range, out error))
        {
            return null;
        }

        var unit = row.Unit.Trim();
        tag = tag with { Unit = unit.Length == 0 ? null : unit, Scale = scale, Range = range };
        error = TagRules.Problem(tag)?.Message;
        return error is null ? tag : null;
    }

    internal override IEnumerable<string> Check(WizardContext context)
    {
        var symbols = new HashSet<string>(context.EarlierSymbols, StringComparer.OrdinalIgnoreCase);
        var problems = new List<string>();
        for (var i = 0; i < Cells.Count; i++)
        {
            var row = Cells[i];
            var use = row.Writable ? AddressUse.Write : AddressUse.Read;
            var error = WizardAddress.Check(row.Address, context, use, _ => null, out var address);
            error ??= row.Format.Fits(address.Width) ? null : $"{row.Format} cannot show {address}";
            if (error is null)
            {
                Tag(row, address, out error);
            }

            error ??= string.IsNullOrWhiteSpace(row.Symbol) ? "the symbol is empty" : null;
            error ??= WizardText.Check(TextRule.Symbol, row.Symbol) ?? WizardText.Check(TextRule.Description, row.Description);
            error ??= symbols.Add(row.Symbol.Trim()) ? null : $"symbol '{row.Symbol.Trim()}' is already used";
            row.Error = error;
            if (error is not null)
            {
                problems.Add($"Cell {i + 1} ({(string.IsNullOrWhiteSpace(row.Address) ? "no address" : row.Address.Trim())}): {error}.");
            }
        }

        MoveUpCommand.NotifyCanExecuteChanged();
        MoveDownCommand.NotifyCanExecuteChanged();
        return problems;
    }
}
