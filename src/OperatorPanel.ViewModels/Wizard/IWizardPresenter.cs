using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// Shows the five wizard pages to the operator: the App opens WizardWindow modally over the wizard and
/// returns <see cref="ProjectWizardViewModel.Result"/> after Finish, or null when the window was cancelled or closed.
/// Tests press the buttons themselves.
/// </summary>
public interface IWizardPresenter
{
    Task<PanelProject?> ShowAsync(ProjectWizardViewModel wizard);
}
