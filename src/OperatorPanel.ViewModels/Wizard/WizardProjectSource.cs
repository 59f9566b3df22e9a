using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Shell;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>File > New through the five wizard pages (seed 000 §7); null when the operator cancels.</summary>
public sealed class WizardProjectSource : INewProjectSource
{
    private readonly IWizardPresenter _presenter;
    private readonly IConnectionTester _tester;
    private readonly ISerialPortCatalog _ports;

    /// <param name="presenter">Shows the wizard window.</param>
    /// <param name="tester">Step 5's "test connection"; wrap it in <see cref="PortInUseGuard"/> so a port the panel is connected on is not opened twice.</param>
    /// <param name="ports">The ports offered on step 5.</param>
    public WizardProjectSource(IWizardPresenter presenter, IConnectionTester tester, ISerialPortCatalog ports)
    {
        ArgumentNullException.ThrowIfNull(presenter);
        ArgumentNullException.ThrowIfNull(tester);
        ArgumentNullException.ThrowIfNull(ports);
        (_presenter, _tester, _ports) = (presenter, tester, ports);
    }

    public Task<PanelProject?> CreateAsync() => _presenter.ShowAsync(new ProjectWizardViewModel(_tester, _ports));
}
