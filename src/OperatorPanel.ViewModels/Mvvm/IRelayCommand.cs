using System.Windows.Input;

namespace OperatorPanel.ViewModels.Mvvm;

/// <summary>A command whose view model says when its CanExecute may have changed (CommunityToolkit.Mvvm's shape).</summary>
public interface IRelayCommand : ICommand
{
    void NotifyCanExecuteChanged();
}
