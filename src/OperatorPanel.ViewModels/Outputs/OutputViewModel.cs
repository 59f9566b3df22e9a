using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Inputs;

namespace OperatorPanel.ViewModels.Outputs;

/// <summary>
/// An output lamp with its switch. The lamp shows only what the PLC read back (<see cref="IoPointViewModel.Value"/>),
/// never the click: while the write is on the wire the row says "writing", and a failure or mismatch stays on the row.
/// </summary>
public sealed partial class OutputViewModel : IoPointViewModel
{
    private readonly Func<OutputViewModel, Task> _switchAsync;
    private readonly Func<bool> _canSwitch;

    internal OutputViewModel(ProjectStation station, IoSymbol symbol, Func<OutputViewModel, Task> switchAsync, Func<bool> canSwitch)
        : base(station, symbol)
    {
        (_switchAsync, _canSwitch) = (switchAsync, canSwitch);
    }

    /// <summary>The value being written, null when no write is on its way.</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(IsWriting))]
    [NotifyCanExecuteChangedFor(nameof(SwitchCommand))]
    public partial bool? Writing { get; internal set; }

    public bool IsWriting => Writing is not null;

    /// <summary>Why the last write was not confirmed; cleared by the next write.</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(HasWriteError))]
    public partial string? WriteError { get; internal set; }

    public bool HasWriteError => WriteError is not null;

    protected override void OnApplied() => SwitchCommand.NotifyCanExecuteChanged();

    /// <summary>Writes the opposite of the lamp's confirmed state (SwitchCommand).</summary>
    [RelayCommand(CanExecute = nameof(CanSwitch))]
    private Task SwitchAsync() => _switchAsync(this);

    private bool CanSwitch() => _canSwitch() && Value is not null && Writing is null;
}
