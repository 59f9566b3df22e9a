using System.Runtime.CompilerServices;
using OperatorPanel.ViewModels.Mvvm;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>An editable row of a wizard table: every edit is reported to its step, which checks the rows again.</summary>
public abstract class WizardRowViewModel : ObservableObject
{
    private string? _error;

    internal event Action? Edited;

    /// <summary>Why the row is refused, for a red mark beside it; null when it is fine.</summary>
    public string? Error { get => _error; internal set => SetProperty(ref _error, value); }

    protected void Edit<T>(ref T field, T value, [CallerMemberName] string? propertyName = null)
    {
        if (SetProperty(ref field, value, propertyName))
        {
            Edited?.Invoke();
        }
    }
}
