namespace OperatorPanel.ViewModels.Memory;

/// <summary>The editor's state: the text typed, the refusal, the write on its way, the last write's problem.</summary>
public sealed partial class MemoryCellViewModel
{
    private bool _isEditing;
    private string _editText = string.Empty;
    private string? _editError;
    private bool _isWriting;
    private string? _writeError;

    public bool IsEditing
    {
        get => _isEditing;
        internal set
        {
            if (SetProperty(ref _isEditing, value))
            {
                NotifyCommands();
            }
        }
    }

    public string EditText
    {
        get => _editText;
        set => SetProperty(ref _editText, value ?? string.Empty);
    }

    /// <summary>Why the typed value was refused ("VW104: 70000 is out of range..."); nothing was written.</summary>
    public string? EditError
    {
        get => _editError;
        internal set => SetProperty(ref _editError, value);
    }

    public bool IsWriting
    {
        get => _isWriting;
        internal set
        {
            if (SetProperty(ref _isWriting, value))
            {
                NotifyCommands();
            }
        }
    }

    /// <summary>Why the last write was not confirmed (refused, read back different, link failure); cleared by the next.</summary>
    public string? WriteError
    {
        get => _writeError;
        internal set => SetProperty(ref _writeError, value);
    }
}
