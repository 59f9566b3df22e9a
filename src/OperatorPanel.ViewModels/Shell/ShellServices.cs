using OperatorPanel.Core.Line;
using OperatorPanel.Historian;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>What the App gives the shell: its dialogs, the line connector (serial ports), the demo, the wizard, the history folder and the alarm sound.</summary>
/// <param name="Dialogs">Questions and error messages.</param>
/// <param name="Files">Open and save file pickers, and the folder picker of Generate PLC code.</param>
/// <param name="Connector">Real serial ports for Connect.</param>
/// <param name="Demo">The sample project and simulated line for the Demo command; null disables the command.</param>
/// <param name="NewProjects">File > New: a <see cref="WizardProjectSource"/>, or <see cref="StarterProjectSource"/> without a wizard.</param>
/// <param name="Wizards">Shows the wizard window for Edit project; null disables the command.</param>
/// <param name="ConnectionTester">The wizard's "test connection" (the shell guards it with <see cref="PortInUseGuard"/>).</param>
/// <param name="Ports">The serial ports the wizard's link page offers.</param>
/// <param name="LayoutPath">The per-user window layout file (<see cref="Docking.DockingViewModel"/>); null keeps the layout for this run only.</param>
/// <param name="ReadmePath">The README installed beside the program, for Help > About; null: beside this assembly.</param>
/// <param name="Documents">Opens the README from Help > About and the alarm journal's print page.</param>
/// <param name="History">Where the projects' history databases are; null: no history (tests that do not look at it).</param>
/// <param name="Sound">The alarm tones; null: a silent panel.</param>
/// <param name="PrintFolder">Where print pages are written; null: the temp folder.</param>
public sealed record ShellServices(
    IDialogService Dialogs,
    IFileDialogService Files,
    ILineConnector Connector,
    IDemoSource? Demo,
    INewProjectSource NewProjects,
    IWizardPresenter? Wizards = null,
    IConnectionTester? ConnectionTester = null,
    ISerialPortCatalog? Ports = null,
    string? LayoutPath = null,
    string? ReadmePath = null,
    IDocumentLauncher? Documents = null,
    HistoryFolder? History = null,
    IAlarmSound? Sound = null,
    string? PrintFolder = null);
