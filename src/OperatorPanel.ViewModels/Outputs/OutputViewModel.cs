using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Inputs;
using OperatorPanel.ViewModels.Mvvm;

namespace OperatorPanel.ViewModels.Outputs;

/// <summary>
/// An output lamp with its switch. The lamp shows only what the PLC read back (<see cref="IoPointViewModel.Value"/>),
/// never the click: while the write is on the wire the row says "writing", and a failure or mismatch stays on the row.
/// </summary>
public sealed class OutputViewModel : IoPointViewModel
{
    private readonly Func<bool> _canSwitch;
    private bool? _writing;
    private string? _writeError;

    internal OutputViewModel(ProjectStation station, IoSymbol symbol, Func<OutputViewModel, Task> switchAsync, Func<bool> canSwitch)
        : base(station, symbol)
    {
        _canSwitch = canSwitch;
        SwitchCommand = new AsyncRelayCommand(() => switchAsync(this), () => _canSwitch() && Value is not null && _writing is null);
    }

    /// <summary>Writes the opposite of the lamp's confirmed state.</summary>
    public AsyncRelayCommand SwitchCommand { get; }

    /// <summary>The value being written, null when no write is on its way.</summary>
    public bool? Writing
    {
        get => _writing;
        internal set
        {
            if (SetProperty(ref _writing, value))
            {
                OnPropertyChanged(nameof(IsWriting));
                SwitchCommand.NotifyCanExecuteChanged();
            }
        }
    }

    public bool IsWriting => Writing is not null;

    /// <summary>Why the last write was not confirmed; cleared by the next write.</summary>
    public string? WriteError
    {
        get => _writeError;
        internal set
        {
            if (SetProperty(ref _writeError, value))
            {
                OnPropertyChanged(nameof(HasWriteError));
            }
        }
    }

    public bool HasWriteError => WriteError is not null;

    protected override void OnApplied() => SwitchCommand.NotifyCanExecuteChanged();
}
