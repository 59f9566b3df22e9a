namespace OperatorPanel.ViewModels.Services;

/// <summary>Opens a document the panel wrote (the alarm journal's print page) in the program Windows has for it.</summary>
public interface IDocumentLauncher
{
    /// <summary>False with the reason when nothing could open it.</summary>
    bool TryOpen(string path, out string? error);
}
