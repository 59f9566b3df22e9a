using System.Collections.Immutable;
using System.Collections.ObjectModel;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// Step 2: names for input and output bits, typed in two tables or pasted from a Micro/WIN symbol table
/// (<see cref="SymbolTableImport"/>). A pasted symbol for an address already listed replaces that row's symbol and comment.
/// </summary>
public sealed partial class IoSymbolsStepViewModel : WizardStepViewModel
{
    private readonly Func<CpuProfile> _cpu;

    internal IoSymbolsStepViewModel(IEnumerable<IoSymbol> inputs, IEnumerable<IoSymbol> outputs, Func<CpuProfile> cpu)
    {
        _cpu = cpu;
        Inputs = new ObservableCollection<IoSymbolRowViewModel>(inputs.Select(s => new IoSymbolRowViewModel(s)));
        Outputs = new ObservableCollection<IoSymbolRowViewModel>(outputs.Select(s => new IoSymbolRowViewModel(s)));
        Track(Inputs);
        Track(Outputs);
    }

    public override int Number => 2;

    public override string Title => "Input and output symbols";

    public ObservableCollection<IoSymbolRowViewModel> Inputs { get; }

    public ObservableCollection<IoSymbolRowViewModel> Outputs { get; }

    /// <summary>What the last paste did, e.g. "Pasted 3 inputs and 2 outputs; 1 line rejected."</summary>
    [ObservableProperty]
    public partial string? PasteReport { get; private set; }

    /// <summary>The lines the last paste rejected: "line 4: VW100 is not an input or output bit; ...".</summary>
    public ObservableCollection<string> RejectedLines { get; } = [];

    [RelayCommand]
    private void AddInput() => Inputs.Add(new IoSymbolRowViewModel());

    [RelayCommand]
    private void AddOutput() => Outputs.Add(new IoSymbolRowViewModel());

    [RelayCommand]
    private void Remove(IoSymbolRowViewModel? row)
    {
        if (row is not null && !Inputs.Remove(row))
        {
            Outputs.Remove(row);
        }
    }

    /// <summary>PasteCommand: takes the clipboard text of a Micro/WIN symbol table.</summary>
    [RelayCommand]
    public void Paste(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var import = SymbolTableImport.Parse(text);
        Merge(Inputs, import.Inputs);
        Merge(Outputs, import.Outputs);
        RejectedLines.Clear();
        foreach (var rejection in import.Rejected)
        {
            RejectedLines.Add(rejection.ToString());
        }

        var rejected = import.Rejected.Length;
        PasteReport = $"Pasted {import.Inputs.Length} input{Plural(import.Inputs.Length)} and {import.Outputs.Length} output{Plural(import.Outputs.Length)}; "
            + $"{rejected} line{Plural(rejected)} rejected.";
    }

    internal IReadOnlySet<string> Symbols() =>
        Inputs.Concat(Outputs).Select(r => r.Symbol.Trim()).Where(s => s.Length > 0).ToHashSet(StringComparer.OrdinalIgnoreCase);

    internal ImmutableArray<IoSymbol> BuildInputs() => [.. Inputs.Select(r => Build(r))];

    internal ImmutableArray<IoSymbol> BuildOutputs() => [.. Outputs.Select(r => Build(r))];

    internal override IEnumerable<string> Check(WizardContext context)
    {
        var symbols = new HashSet<string>(StringComparer.OrdinalIgnoreCase);
        return CheckTable("Input", Inputs, MemoryArea.I, context, symbols).Concat(CheckTable("Output", Outputs, MemoryArea.Q, context, symbols)).ToList();
    }

    private static IEnumerable<string> CheckTable(
        string noun, ObservableCollection<IoSymbolRowViewModel> rows, MemoryArea area, WizardContext context, HashSet<string> symbols)
    {
        var addresses = new HashSet<PlcAddress>();
        var kind = area == MemoryArea.I ? "an input is an I bit such as I0.0" : "an output is a Q bit such as Q0.0";
        for (var i = 0; i < rows.Count; i++)
        {
            var row = rows[i];
            var error = WizardAddress.Check(row.Address, context, AddressUse.Read, a => WizardAddress.IsBitOf(a, area) ? null : $"{kind}, not {a}", out var address);
            error ??= addresses.Add(address) ? null : $"{address} is listed twice";
            error ??= string.IsNullOrWhiteSpace(row.Symbol) ? "the symbol is empty" : null;
            error ??= WizardText.Check(TextRule.Symbol, row.Symbol) ?? WizardText.Check(TextRule.Description, row.Description);
            error ??= symbols.Add(row.Symbol.Trim()) ? null : $"symbol '{row.Symbol.Trim()}' is used twice";
            row.Error = error;
            if (error is not null)
            {
                yield return $"{noun} row {i + 1} ({Shown(row.Address)}): {error}.";
            }
        }
    }

    private static string Shown(string text) => string.IsNullOrWhiteSpace(text) ? "no address" : text.Trim();

    private static IoSymbol Build(IoSymbolRowViewModel row) => new(row.Symbol.Trim(), PlcAddress.Parse(row.Address.Trim()), row.Description.Trim());

    private static void Merge(ObservableCollection<IoSymbolRowViewModel> rows, IEnumerable<IoSymbol> pasted)
    {
        foreach (var symbol in pasted)
        {
            var existing = rows.FirstOrDefault(r => PlcAddress.TryParse(r.Address.Trim(), out var a, out _) && a == symbol.Address);
            if (existing is null)
            {
                rows.Add(new IoSymbolRowViewModel(symbol));
            }
            else
            {
                existing.Symbol = symbol.Symbol;
                existing.Description = symbol.Description;
            }
        }
    }

    /// <summary>
    /// Step 1's CPU changed from <paramref name="previous"/>: tables that still hold exactly the starter list of that CPU
    /// (placeholder symbols of its on-board points, as a new project starts) take the new CPU's, so a CPU 226 starts with
    /// I0.0-I2.7 and Q0.0-Q1.7, not a CPU 224's I1.5 and Q1.1. Tables the user edited stay as they are.
    /// </summary>
    internal void FollowCpu(CpuProfile previous)
    {
        var before = Starter(previous);
        if (Same(Inputs, before.Inputs) && Same(Outputs, before.Outputs))
        {
            FillLocalPoints();
        }
    }

    private static bool Same(ObservableCollection<IoSymbolRowViewModel> rows, ImmutableArray<IoSymbol> starter) =>
        rows.Count == starter.Length
        && rows.Zip(starter).All(p => p.First.Symbol == p.Second.Symbol && p.First.Address == p.Second.Address.ToString() && p.First.Description == p.Second.Description);

    private static ProjectStation Starter(CpuProfile cpu) => StarterProject.Create(string.Empty, cpu, new Core.Addressing.Station(2), "COM1").Stations[0];

    /// <summary>FillLocalPointsCommand: replaces both tables with the CPU's on-board points and placeholder symbols (I0.0 Input_0_0 ...).</summary>
    [RelayCommand]
    private void FillLocalPoints()
    {
        var starter = Starter(_cpu());
        Inputs.Clear();
        Outputs.Clear();
        foreach (var input in starter.Inputs)
        {
            Inputs.Add(new IoSymbolRowViewModel(input));
        }

        foreach (var output in starter.Outputs)
        {
            Outputs.Add(new IoSymbolRowViewModel(output));
        }
    }

    private static string Plural(int count) => count == 1 ? string.Empty : "s";
}
