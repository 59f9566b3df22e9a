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

    internal MemoryCellViewModel(ProjectStation station, ProjectTag tag, MemoryViewModel owner)
    {
        (Station, Tag, _owner) = (station, tag, owner);
        FormatChoices = [.. Enum.GetValues<DisplayFormat>().Where(f => f.Fits(tag.Address.Width))];
    }

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

    /// <summary>Only the formats that fit the width: Bool for a bit, Float only for a double word (DisplayFormats.Fits).</summary>
    public IReadOnlyList<DisplayFormat> FormatChoices { get; }

    /// <summary>Changing it edits the project (it becomes unsaved) through <see cref="ChangeFormatCommand"/>, which owns the edit's task.</summary>
    public DisplayFormat Format
    {
        get => Tag.Format;
        set
        {
            if (value != Tag.Format)
            {
                ChangeFormatCommand.Execute(value);
            }
        }
    }

    public ValueQuality Quality => _value?.Quality ?? ValueQuality.Bad;

    /// <summary>Why the value is stale or bad; null when good.</summary>
    public string? QualityText => Quality == ValueQuality.Good ? null : _value?.Error ?? "not read yet";

    /// <summary>A value was read (good, or stale and kept); false before the first read.</summary>
    internal bool HasValue => _value is { HasValue: true };

    public string ValueText => _value is { HasValue: true } value
        ? ValueFormatter.Format(value.Raw.AsSpan(), Tag.Address.Width, Tag.Format)
        : "-";

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

    /// <summary>The format combo box's edit; never throws (the owner reports a failure on the status line).</summary>
    [RelayCommand]
    private Task ChangeFormatAsync(DisplayFormat format) => _owner.ChangeFormatAsync(this, format);

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
        EditText = ValueText == "-" ? string.Empty : ValueText;
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
