namespace OperatorPanel.ViewModels.Services;

/// <summary>Opens a document in the program Windows associates with it (the App: the shell's open verb).</summary>
public interface IDocumentLauncher
{
    /// <summary>False with the reason when the document could not be opened.</summary>
    bool TryOpen(string path, out string? error);
}
