using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Opens nothing; keeps the paths it was asked to open.</summary>
internal sealed class RecordingDocuments : IDocumentLauncher
{
    public List<string> Opened { get; } = [];

    public bool TryOpen(string path, out string? error)
    {
        Opened.Add(path);
        error = null;
        return true;
    }
}
