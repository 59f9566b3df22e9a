namespace OperatorPanel.ViewModels.Mvvm;

/// <summary>
/// An asynchronous command that cannot run twice at once (a second click while a write is on the wire does nothing),
/// so no PLC write is ever repeated by an impatient operator. Tests await <see cref="ExecuteAsync"/> directly.
/// </summary>
public sealed class AsyncRelayCommand : IRelayCommand
{
    private readonly Func<Task> _execute;
    private readonly Func<bool>? _canExecute;

    public AsyncRelayCommand(Func<Task> execute, Func<bool>? canExecute = null)
    {
        ArgumentNullException.ThrowIfNull(execute);
        (_execute, _canExecute) = (execute, canExecute);
    }

    public event EventHandler? CanExecuteChanged;

    public bool IsRunning { get; private set; }

    public bool CanExecute(object? parameter) => !IsRunning && (_canExecute?.Invoke() ?? true);

    /// <summary>Fire-and-forget entry for the view; the task's faults are the view model's to catch and show.</summary>
    public async void Execute(object? parameter) => await ExecuteAsync();

    public async Task ExecuteAsync()
    {
        if (!CanExecute(null))
        {
            return;
        }

        IsRunning = true;
        NotifyCanExecuteChanged();
        try
        {
            await _execute();
        }
        finally
        {
            IsRunning = false;
            NotifyCanExecuteChanged();
        }
    }

    public void NotifyCanExecuteChanged() => CanExecuteChanged?.Invoke(this, EventArgs.Empty);
}
