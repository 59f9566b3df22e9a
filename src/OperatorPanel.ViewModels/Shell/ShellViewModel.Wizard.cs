using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.ViewModels.Generate;
using OperatorPanel.ViewModels.Help;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>
/// Edit project (the wizard's five pages over the selected station, seed 000 §7: "the project can be freely edited
/// later"), Generate PLC code for the project's stations, and Help > About: the shell's dialogs.
/// </summary>
public sealed partial class ShellViewModel
{
    /// <summary>Opens Generate PLC code: sets <see cref="GenerateCode"/>, which the App shows while it is not null.</summary>
    public IRelayCommand GenerateCodeCommand { get; }

    /// <summary>The station Edit project and Generate PLC code start on (index into the project's stations).</summary>
    [ObservableProperty]
    public partial int SelectedStationIndex { get; set; }

    /// <summary>The open Generate PLC code dialog; null when closed. The App closes it with <see cref="CloseGenerateCode"/>.</summary>
    [ObservableProperty]
    public partial GenerateCodeViewModel? GenerateCode { get; private set; }

    public void CloseGenerateCode() => GenerateCode = null;

    /// <summary>Help > About while open (the App shows it as a dialog and closes it with <see cref="CloseAbout"/>); null otherwise.</summary>
    [ObservableProperty]
    public partial AboutViewModel? About { get; private set; }

    public void CloseAbout() => About = null;

    [RelayCommand]
    private void ShowAbout() =>
        About = new AboutViewModel(_services.ReadmePath ?? Path.Combine(AppContext.BaseDirectory, "README.txt"), _services.Documents);

    /// <summary>EditProjectCommand: the wizard on the station at <see cref="SelectedStationIndex"/>; Finish replaces the project (now unsaved).</summary>
    [RelayCommand(CanExecute = nameof(CanEditProject))]
    private async Task EditProjectAsync()
    {
        if (_services is not { Wizards: { } presenter, ConnectionTester: { } tester, Ports: { } ports })
        {
            StatusLine.ShowError("Editing the project needs the wizard, which this build does not offer");
            return;
        }

        var index = Math.Clamp(SelectedStationIndex, 0, Session.Project.Stations.Length - 1);
        var wizard = new ProjectWizardViewModel(Session.Project, index, new PortInUseGuard(tester, Session), ports, _time);
        if (await presenter.ShowAsync(wizard) is not { } edited)
        {
            return;
        }

        try
        {
            // EditProjectAsync raises ProjectChanged(Edited): the shell marks the project unsaved, the windows rebuild,
            // and a connected line polls the new watch list (or reconnects when ports or stations changed).
            await Session.EditProjectAsync(edited);
            StatusLine.Show($"Station {edited.Stations[index].Name} edited; save to keep the changes");
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _logger.Error(exception, "Applying the edited project failed");
            StatusLine.ShowError($"The edited project was kept but the line could not follow: {exception.Message}");
        }
    }

    // Not while a bus is read over PPI: the wizard would take the in-memory PPI link for the project's.
    private bool CanEditProject() => HasProject && _services.Wizards is not null && !Session.IsReadingOverPpi;

    private void OpenGenerateCode() =>
        GenerateCode = new GenerateCodeViewModel(Session.Project, Math.Clamp(SelectedStationIndex, 0, Session.Project.Stations.Length - 1), _services.Files);
}
