using System.ComponentModel;
using System.Runtime.CompilerServices;

namespace OperatorPanel.ViewModels.Mvvm;

/// <summary>
/// Property change notification for view models. Hand-written because the registry copy serves no
/// CommunityToolkit.Mvvm; the members mirror the toolkit's so a later switch is a rename of the base class only.
/// </summary>
public abstract class ObservableObject : INotifyPropertyChanged
{
    public event PropertyChangedEventHandler? PropertyChanged;

    protected bool SetProperty<T>(ref T field, T value, [CallerMemberName] string? propertyName = null)
    {
        if (EqualityComparer<T>.Default.Equals(field, value))
        {
            return false;
        }

        field = value;
        OnPropertyChanged(propertyName);
        return true;
    }

    protected void OnPropertyChanged([CallerMemberName] string? propertyName = null) =>
        PropertyChanged?.Invoke(this, new PropertyChangedEventArgs(propertyName));
}
