using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Plays the operator in the wizard window: runs <see cref="Operator"/> on the pages, then returns the result (null = cancelled).</summary>
internal sealed class ScriptedWizardPresenter : IWizardPresenter
{
    public Func<ProjectWizardViewModel, Task> Operator { get; set; } = wizard =>
    {
        wizard.FinishCommand.Execute(null);
        return Task.CompletedTask;
    };

    public List<ProjectWizardViewModel> Shown { get; } = [];

    public bool Cancel { get; set; }

    public async Task<PanelProject?> ShowAsync(ProjectWizardViewModel wizard)
    {
        Shown.Add(wizard);
        await Operator(wizard);
        return Cancel ? null : wizard.Result;
    }
}
