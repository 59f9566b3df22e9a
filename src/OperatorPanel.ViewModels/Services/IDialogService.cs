namespace OperatorPanel.ViewModels.Services;

/// <summary>Questions and messages that need the operator; the App shows them as WPF dialogs, tests answer them from a script.</summary>
public interface IDialogService
{
    /// <summary>
    /// A yes/no question, e.g. "Set Q0.3 (Conveyor) from 0 to 1?"; true = go ahead. <paramref name="noByDefault"/>: Enter
    /// answers No (a question whose Yes stops the line).
    /// </summary>
    Task<bool> ConfirmAsync(string title, string message, bool noByDefault = false);

    /// <summary>"Save changes to X?" before the project is closed or replaced.</summary>
    Task<SaveChangesAnswer> AskSaveChangesAsync(string projectName);

    /// <summary>An error the operator must read; the app goes on afterwards.</summary>
    Task ShowErrorAsync(string title, string message);
}
