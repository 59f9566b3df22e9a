using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.ViewModels.Memory;

/// <summary>
/// One memory cell (a <see cref="ProjectTag"/>) as a row of the Memory window: its value as last read, and an in-place
/// editor (begin, type, commit or Esc to cancel). The value shown is always the PLC's, a written value only once read back.
/// </summary>
public sealed partial class MemoryCellViewModel : ObservableObject
{
    private readonly MemoryViewModel _owner;
    private PolledValue? _value;

    internal MemoryCellViewModel(ProjectStation station, ProjectTag tag, MemoryViewModel owner) => (Station, Tag, _owner) = (station, tag, owner);

    public ProjectStation Station { get; }

    public ProjectTag Tag { get; }

    public string StationName => Station.Name;

    public string Symbol => Tag.Symbol;

    public PlcAddress PlcAddress => Tag.Address;

    public string Address => Tag.Address.ToString();

    public string WidthText => Tag.Address.Width switch
    {
        AccessWidth.Bit => "bit",
        AccessWidth.Byte => "byte",
        AccessWidth.Word => "word",
        AccessWidth.DoubleWord => "double word",
    };

    public string Description => Tag.Description;

    public bool Writable => Tag.Writable;

    /// <summary>
    /// How the value is shown: a project setting (the wizard, File > Edit project), not an operator's choice in the live
    /// view, so every operator reads a cell the same way and a value is typed in the units it is shown in.
    /// </summary>
    public DisplayFormat Format => Tag.Format;

    /// <summary>"unsigned", "float, %, 0..1000 -> 0..100": the format with the tag's unit and scale, for the Format column.</summary>
    public string FormatText => string.Join(", ", new[] { Tag.Format.ToString().ToLowerInvariant(), Tag.Unit, Tag.Scale?.ToString() }.OfType<string>());

    /// <summary>"1..8 ms": what the operator may write, in the shown units; null when only the address's width limits it.</summary>
    public string? RangeText => Tag.Range is { } range ? range + (Tag.Unit is { } unit ? " " + unit : string.Empty) : null;

    public ValueQuality Quality => _value?.Quality ?? ValueQuality.Bad;

    /// <summary>Why the value is stale or bad; null when good.</summary>
    public string? QualityText => Quality == ValueQuality.Good ? null : _value?.Error ?? "not read yet";

    /// <summary>A value was read (good, or stale and kept); false before the first read.</summary>
    internal bool HasValue => _value is { HasValue: true };

    /// <summary>The value in the tag's format, scaled to its engineering units, with its unit ("55.2 %"); "-" when never read.</summary>
    public string ValueText => _value is { HasValue: true } value ? TagValues.Format(Tag, value.Raw.AsSpan()) : "-";

    internal bool CanEdit => Writable && _owner.CanWrite();

    /// <summary>The cell's subscription to its address (PanelSession.Values): every value read, on the UI thread.</summary>
    internal void Apply(PolledValue value)
    {
        _value = value;
        OnPropertyChanged(nameof(ValueText));
        OnPropertyChanged(nameof(Quality));
        OnPropertyChanged(nameof(QualityText));
    }

    [RelayCommand(CanExecute = nameof(CanCommitEdit))]
    private Task CommitEditAsync() => _owner.CommitAsync(this);

    private bool CanBeginEdit() => CanEdit && !IsEditing;

    private bool CanCommitEdit() => IsEditing && !IsWriting;

    internal void NotifyCommands()
    {
        BeginEditCommand.NotifyCanExecuteChanged();
        CommitEditCommand.NotifyCanExecuteChanged();
        CancelEditCommand.NotifyCanExecuteChanged();
    }

    [RelayCommand(CanExecute = nameof(CanBeginEdit))]
    private void BeginEdit()
    {
        EditText = _value is { HasValue: true } value && Tag.Unit is { } unit && ValueText.EndsWith(" " + unit, StringComparison.Ordinal)
            ? ValueText[..^(unit.Length + 1)]
            : ValueText == "-" ? string.Empty : ValueText;
        EditError = null;
        IsEditing = true;
    }

    [RelayCommand(CanExecute = nameof(IsEditing))]
    private void CancelEdit()
    {
        EditError = null;
        IsEditing = false;
    }
}
