using CommunityToolkit.Mvvm.ComponentModel;

namespace OperatorPanel.ViewModels.Memory;

/// <summary>The editor's state: the text typed, the refusal, the write on its way, the last write's problem.</summary>
public sealed partial class MemoryCellViewModel
{
    [ObservableProperty]
    [NotifyCanExecuteChangedFor(nameof(BeginEditCommand), nameof(CommitEditCommand), nameof(CancelEditCommand))]
    public partial bool IsEditing { get; internal set; }

    public string EditText
    {
        get;
        set => SetProperty(ref field, value ?? string.Empty);
    }

    = string.Empty;

    /// <summary>Why the typed value was refused ("VW104: 70000 is out of range..."); nothing was written.</summary>
    [ObservableProperty]
    public partial string? EditError { get; internal set; }

    [ObservableProperty]
    [NotifyCanExecuteChangedFor(nameof(CommitEditCommand))]
    public partial bool IsWriting { get; internal set; }

    /// <summary>Why the last write was not confirmed (refused, read back different, link failure); cleared by the next.</summary>
    [ObservableProperty]
    public partial string? WriteError { get; internal set; }
}
