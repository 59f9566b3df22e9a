using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>What the App gives the shell: its dialogs, the line connector (serial ports), and the demo.</summary>
/// <param name="Dialogs">Questions and error messages.</param>
/// <param name="Files">Open and save file pickers.</param>
/// <param name="Connector">Real serial ports for Connect.</param>
/// <param name="Demo">The sample project and simulated line for the Demo command; null disables the command.</param>
/// <param name="NewProjects">File > New; <see cref="StarterProjectSource"/> until the wizard is wired in.</param>
public sealed record ShellServices(
    IDialogService Dialogs,
    IFileDialogService Files,
    ILineConnector Connector,
    IDemoSource? Demo,
    INewProjectSource NewProjects);
