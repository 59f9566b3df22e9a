using System.Runtime.CompilerServices;
using CommunityToolkit.Mvvm.ComponentModel;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>An editable row of a wizard table: every edit is reported to its step, which checks the rows again.</summary>
public abstract partial class WizardRowViewModel : ObservableObject
{
    internal event Action? Edited;

    /// <summary>Why the row is refused, for a red mark beside it; null when it is fine.</summary>
    [ObservableProperty]
    public partial string? Error { get; internal set; }

    protected void Edit<T>(ref T field, T value, [CallerMemberName] string? propertyName = null)
    {
        if (SetProperty(ref field, value, propertyName))
        {
            Edited?.Invoke();
        }
    }
}
