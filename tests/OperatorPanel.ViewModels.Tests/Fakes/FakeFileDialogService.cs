using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Returns the paths a test set; null means the operator cancelled.</summary>
internal sealed class FakeFileDialogService : IFileDialogService
{
    public string? FileToOpen { get; set; }

    public string? FileToSave { get; set; }

    public string? PickFileToOpen(string title, string filter) => FileToOpen;

    public string? PickFileToSave(string title, string filter, string suggestedFileName) => FileToSave;

    public string? Folder { get; set; }

    public string? PickFolder(string title) => Folder;
}
