using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>What the alarm window needs from the App besides the line.</summary>
/// <param name="Files">The journal's CSV export asks where to save.</param>
/// <param name="Sound">The alarm tones.</param>
/// <param name="Documents">Opens the journal's print page; null: the page is written and its path shown.</param>
/// <param name="PrintFolder">Where the print pages are written.</param>
/// <param name="User">Who acknowledges, as the journal records it.</param>
public sealed record AlarmServices(IFileDialogService Files, IAlarmSound Sound, IDocumentLauncher? Documents, string PrintFolder, string User);
