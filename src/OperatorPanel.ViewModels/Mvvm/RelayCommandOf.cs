namespace OperatorPanel.ViewModels.Mvvm;

/// <summary>A synchronous command with a typed parameter (a row, an item); a parameter of another type cannot execute.</summary>
public sealed class RelayCommand<T> : IRelayCommand
{
    private readonly Action<T> _execute;
    private readonly Func<T, bool>? _canExecute;

    public RelayCommand(Action<T> execute, Func<T, bool>? canExecute = null)
    {
        ArgumentNullException.ThrowIfNull(execute);
        (_execute, _canExecute) = (execute, canExecute);
    }

    public event EventHandler? CanExecuteChanged;

    public bool CanExecute(object? parameter) => parameter is T value && (_canExecute?.Invoke(value) ?? true);

    public void Execute(object? parameter)
    {
        if (parameter is T value && CanExecute(value))
        {
            _execute(value);
        }
    }

    public void NotifyCanExecuteChanged() => CanExecuteChanged?.Invoke(this, EventArgs.Empty);
}
