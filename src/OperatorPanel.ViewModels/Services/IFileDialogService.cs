namespace OperatorPanel.ViewModels.Services;

/// <summary>File pickers; null = the operator cancelled.</summary>
public interface IFileDialogService
{
    /// <summary>Asks for an existing file; <paramref name="filter"/> is WPF filter text, e.g. "Operator Panel projects (*.opproj)|*.opproj".</summary>
    string? PickFileToOpen(string title, string filter);

    string? PickFileToSave(string title, string filter, string suggestedFileName);

    string? PickFolder(string title);
}
