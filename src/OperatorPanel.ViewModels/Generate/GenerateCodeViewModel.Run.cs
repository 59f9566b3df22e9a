using System.Collections.ObjectModel;
using System.Globalization;
using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Options;
using OperatorPanel.ViewModels.Mvvm;

namespace OperatorPanel.ViewModels.Generate;

/// <summary>Generate (HandlerGenerator, and HandlerMerger when a program is given), the figures, the preview and Save.</summary>
public sealed partial class GenerateCodeViewModel
{
    /// <summary>An exported Micro/WIN program larger than this is not a program block.</summary>
    private const long MaxProgramBytes = 8 * 1024 * 1024;

    private HandlerGenerationResult? _result;
    private MergeResult? _merge;
    private string? _mergeProgramPath;
    private string _preview = string.Empty;
    private string? _message;

    public RelayCommand GenerateCommand { get; }

    /// <summary>Asks for a folder and writes the files; enabled after a Generate without errors.</summary>
    public RelayCommand SaveCommand { get; }

    public RelayCommand BrowseMergeCommand { get; }

    public RelayCommand ClearMergeCommand { get; }

    /// <summary>A program exported from Micro/WIN (.awl) to merge the handler into; null = the handler alone.</summary>
    public string? MergeProgramPath
    {
        get => _mergeProgramPath;
        set
        {
            if (SetProperty(ref _mergeProgramPath, value))
            {
                ClearMergeCommand.NotifyCanExecuteChanged();
                ClearResult();
            }
        }
    }

    /// <summary>Why nothing was generated or merged (and merge warnings), in ID and line order.</summary>
    public ObservableCollection<GenerateDiagnosticRow> Diagnostics { get; } = [];

    /// <summary>The figures: V range, instructions, interrupt events, one line per block.</summary>
    public ObservableCollection<string> Stats { get; } = [];

    /// <summary>The .awl text that Save writes (the merged program when merging).</summary>
    public string Preview { get => _preview; private set => SetProperty(ref _preview, value); }

    /// <summary>What Generate or Save did, or why not; null before either.</summary>
    public string? Message { get => _message; private set => SetProperty(ref _message, value); }

    public bool CanSave => _result is { Ok: true } && _merge is null or { Ok: true };

    private void Generate()
    {
        ClearResult();
        if (!TryReadOptions(out var options))
        {
            Message = "Fix the settings marked INPUT, then generate again.";
            return;
        }

        var result = HandlerGenerator.Generate(options);
        foreach (var diagnostic in result.Diagnostics)
        {
            Diagnostics.Add(new GenerateDiagnosticRow(diagnostic.Id, 0, diagnostic.Message));
        }

        if (!result.Ok)
        {
            Message = "These settings are impossible on this CPU; nothing was generated.";
            return;
        }

        if (MergeProgramPath is { } path && !TryMerge(path, options))
        {
            return;
        }

        _result = result;
        Stats.Add($"V memory: {result.Stats!.VRange} ({result.Stats.VBytes} bytes)");
        Stats.Add(string.Create(CultureInfo.InvariantCulture, $"Instructions: {result.Stats.Instructions}"));
        Stats.Add($"Interrupt events: {string.Join(", ", result.Stats.InterruptEvents)} (port {result.Stats.Port})");
        foreach (var block in result.Stats.Blocks)
        {
            Stats.Add($"{block.NumberText} {block.Name}: {block.Purpose}");
        }

        Preview = _merge?.MergedText ?? result.AwlText;
        Message = _merge is null ? "Generated; Save writes the handler, the symbol table and the technician's notes."
            : "Merged without collisions; Save writes the merged program beside the handler's files.";
        NotifySave();
    }

    private void BrowseMerge()
    {
        if (_files.PickFileToOpen("Program exported from Micro/WIN to merge with", "STL programs (*.awl)|*.awl|All files (*.*)|*.*") is { } path)
        {
            MergeProgramPath = path;
        }
    }

    private bool TryMerge(string path, HandlerOptions options)
    {
        if (!AtomicFile.TryReadAll(path, MaxProgramBytes, out var bytes, out var error))
        {
            Message = $"{path}: {error}";
            return false;
        }

        // Micro/WIN exports in the Windows code page; Latin-1 keeps every byte as it was for the merged file.
        var merge = HandlerMerger.Merge(Encoding.Latin1.GetString(bytes), options);
        foreach (var finding in merge.Diagnostics)
        {
            Diagnostics.Add(new GenerateDiagnosticRow(finding.Id, finding.Line, finding.Message, finding.Severity == MergeSeverity.Warning));
        }

        if (!merge.Ok)
        {
            Message = $"{Path.GetFileName(path)} collides with the handler ({merge.Errors.Count()} problem(s)); nothing can be saved.";
            return false;
        }

        _merge = merge;
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
        var delay = Number(ReplyDelay, "reply delay");
        var charTimeout = Number(CharTimeout, "inter-character timeout");
        options = new HandlerOptions
        {
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
            ReplyDelayMs = delay ?? 0,
            CharTimeoutMs = charTimeout ?? 0,
            WriteMask = (WriteQ ? 1 << 2 : 0) | (WriteM ? 1 << 3 : 0) | (WriteV ? 1 << 4 : 0) | (WriteSm ? 1 << 5 : 0),
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
        (_result, _merge) = (null, null);
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
