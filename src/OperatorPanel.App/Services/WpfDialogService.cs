using System.Windows;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.App.Services;

/// <summary>The view models' questions as WPF message boxes, owned by the main window.</summary>
public sealed class WpfDialogService : IDialogService
{
    public Task<bool> ConfirmAsync(string title, string message, bool noByDefault = false) =>
        Task.FromResult(MessageBox.Show(
            Owner(), message, title, MessageBoxButton.YesNo, MessageBoxImage.Question, noByDefault ? MessageBoxResult.No : MessageBoxResult.Yes) == MessageBoxResult.Yes);

    public Task<SaveChangesAnswer> AskSaveChangesAsync(string projectName)
    {
        var answer = MessageBox.Show(
            Owner(), $"Save changes to {projectName}?", "Operator Panel", MessageBoxButton.YesNoCancel, MessageBoxImage.Warning);
        return Task.FromResult(answer switch
        {
            MessageBoxResult.Yes => SaveChangesAnswer.Save,
            MessageBoxResult.No => SaveChangesAnswer.Discard,
            _ => SaveChangesAnswer.Cancel,
        });
    }

    public Task ShowErrorAsync(string title, string message)
    {
        MessageBox.Show(Owner(), message, title, MessageBoxButton.OK, MessageBoxImage.Error);
        return Task.CompletedTask;
    }

    private static Window Owner() => Application.Current.MainWindow;
}
