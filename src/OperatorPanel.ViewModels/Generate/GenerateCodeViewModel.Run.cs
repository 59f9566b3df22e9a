using System.Collections.ObjectModel;
using System.Globalization;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Addressing;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.ViewModels.Generate;

/// <summary>
/// Generate (the <see cref="HandlerPackage"/> <c>opanel generate</c> writes too: handler, and merge when a program is
/// given), the figures, the preview and Save.
/// </summary>
public sealed partial class GenerateCodeViewModel
{
    private HandlerPackage? _package;

    /// <summary>A program exported from Micro/WIN (.awl) to merge the handler into; null = the handler alone.</summary>
    [ObservableProperty]
    [NotifyCanExecuteChangedFor(nameof(ClearMergeCommand))]
    public partial string? MergeProgramPath { get; set; }

    /// <summary>Why nothing was generated or merged (and merge warnings), in ID and line order.</summary>
    public ObservableCollection<GenerateDiagnosticRow> Diagnostics { get; } = [];

    /// <summary>The figures: V range, instructions, interrupt events, one line per block.</summary>
    public ObservableCollection<string> Stats { get; } = [];

    /// <summary>The .awl text that Save writes (the merged program when merging).</summary>
    [ObservableProperty]
    public partial string Preview { get; private set; } = string.Empty;

    /// <summary>What Generate or Save did, or why not; null before either.</summary>
    [ObservableProperty]
    public partial string? Message { get; private set; }

    public bool CanSave => _package is { Ok: true };

    [RelayCommand]
    private void Generate()
    {
        ClearResult();
        if (!TryReadOptions(out var options))
        {
            Message = "Fix the settings marked INPUT, then generate again.";
            return;
        }

        if (!HandlerPackage.TryGenerate(options, FileStem, MergeProgramPath, out var package, out var readError))
        {
            Message = readError;
            return;
        }

        var result = package.Handler;
        foreach (var diagnostic in result.Diagnostics)
        {
            Diagnostics.Add(new GenerateDiagnosticRow(diagnostic.Id, 0, diagnostic.Message));
        }

        if (!result.Ok)
        {
            Message = "These settings are impossible (the list of messages says why); nothing was generated.";
            return;
        }

        if (package.Merge is { } merge && !ShowMerge(merge, MergeProgramPath!))
        {
            return;
        }

        _package = package;
        Stats.Add($"V memory: {result.Stats!.VRange} ({result.Stats.VBytes} bytes)");
        var size = result.Stats.Size;
        Stats.Add(string.Create(CultureInfo.InvariantCulture, $"Instructions: {size.Instructions} in {size.Networks} networks"));
        Stats.Add($"Program size, estimated: {size.EstimateText}; {HandlerSize.BasisText}");
        Stats.Add($"Program memory: {size.ProgramMemoryText}");
        Stats.Add($"For comparison: {HandlerSize.ModbusComparisonText}");
        if (size.Warning is { } warning)
        {
            Diagnostics.Add(new GenerateDiagnosticRow(StlDiagnostics.ProgramMemoryTight, 0, warning, IsWarning: true));
        }

        Stats.Add($"Interrupt events: {string.Join(", ", result.Stats.InterruptEvents)} (port {result.Stats.Port})");
        foreach (var block in result.Stats.Blocks)
        {
            Stats.Add($"{block.NumberText} {block.Name}: {block.Purpose}");
        }

        Preview = package.Merge?.MergedText ?? result.AwlText;
        Message = package.Merge is null ? "Generated; Save writes the handler, the symbol table and the technician's notes."
            : "Merged without collisions; Save writes the merged program beside the handler's files.";
        NotifySave();
    }

    [RelayCommand]
    private void BrowseMerge()
    {
        if (_files.PickFileToOpen("Program exported from Micro/WIN to merge with", "STL programs (*.awl)|*.awl|All files (*.*)|*.*") is { } path)
        {
            MergeProgramPath = path;
        }
    }

    [RelayCommand(CanExecute = nameof(HasMergeProgram))]
    private void ClearMerge() => MergeProgramPath = null;

    private bool HasMergeProgram() => MergeProgramPath is not null;

    partial void OnMergeProgramPathChanged(string? value) => ClearResult();

    /// <summary>Lists the merge's findings; false (nothing to save) when the program collides with the handler.</summary>
    private bool ShowMerge(MergeResult merge, string path)
    {
        foreach (var finding in merge.Diagnostics)
        {
            Diagnostics.Add(new GenerateDiagnosticRow(finding.Id, finding.Line, finding.Message, finding.Severity == MergeSeverity.Warning));
        }

        if (!merge.Ok)
        {
            Message = $"{Path.GetFileName(path)} collides with the handler ({merge.Errors.Count()} problem(s)); nothing can be saved.";
            return false;
        }

        return true;
    }

    private bool TryReadOptions(out HandlerOptions options)
    {
        var station = Station;
        int? buffer = null;
        if (!PlcAddress.TryParse(BufferStart.Trim(), out var address, out var addressError))
        {
            Diagnostics.Add(new GenerateDiagnosticRow("INPUT", 0, $"buffer start '{BufferStart}': {addressError.Message}"));
        }
        else if (address.Area != MemoryArea.V || address.Width != AccessWidth.Byte)
        {
            Diagnostics.Add(new GenerateDiagnosticRow("INPUT", 0, $"buffer start '{BufferStart}': give the first V byte, e.g. VB1000"));
        }
        else
        {
            buffer = address.ByteOffset;
        }

        var sbr = Number(FirstSubroutine, "first SBR");
        var interrupt = Number(FirstInterrupt, "first INT");
        var charTimeout = Number(CharTimeout, "end timer");
        // Protocol 3: the panel speaks it and tells an older handler to regenerate (docs/protocol.md section 8).
        options = new HandlerOptions
        {
            Protocol = 3,
            Cpu = station.Cpu,
            Port = Port,
            BaudRate = station.Link.BaudRate,
            Parity = station.Link.Parity,
            DataBits = station.Link.DataBits,
            StopBits = station.Link.StopBits,
            Station = station.Address.Address,
            BufferStart = buffer,
            FirstSubroutine = sbr,
            FirstInterrupt = interrupt,
            CharTimeoutMs = charTimeout ?? 0,
            // Protocol 3 never writes I or SM (docs/protocol.md section 0): the mask has Q, M and V only.
            WriteMask = (WriteQ ? 1 << 2 : 0) | (WriteM ? 1 << 3 : 0) | (WriteV ? 1 << 4 : 0),
            AllowStop = station.AllowStop,
            Compact = station.Compact,
        };
        return Diagnostics.Count == 0;
    }

    private int? Number(string text, string what)
    {
        if (int.TryParse(text.Trim(), NumberStyles.Integer, CultureInfo.InvariantCulture, out var value))
        {
            return value;
        }

        Diagnostics.Add(new GenerateDiagnosticRow("INPUT", 0, $"{what} '{text}' is not a whole number"));
        return null;
    }

    private void ClearResult()
    {
        _package = null;
        Diagnostics.Clear();
        Stats.Clear();
        Preview = string.Empty;
        Message = null;
        NotifySave();
    }

    private void NotifySave()
    {
        OnPropertyChanged(nameof(CanSave));
        SaveCommand.NotifyCanExecuteChanged();
    }
}
