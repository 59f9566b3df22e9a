using System.Windows;
using OperatorPanel.App.Wizard;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.App.Services;

/// <summary>Shows the wizard window modally over the main window.</summary>
public sealed class WizardPresenter : IWizardPresenter
{
    public Task<PanelProject?> ShowAsync(ProjectWizardViewModel wizard)
    {
        var window = new WizardWindow(wizard) { Owner = Application.Current.MainWindow };
        return Task.FromResult(window.ShowDialog() == true ? wizard.Result : null);
    }
}
