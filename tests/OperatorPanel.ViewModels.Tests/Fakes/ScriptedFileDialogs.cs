using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Answers file pickers with a set path (null = cancelled) and records the titles it was asked.</summary>
internal sealed class ScriptedFileDialogs : IFileDialogService
{
    public string? Answer { get; set; }

    public List<string> Asked { get; } = [];

    public string? PickFileToOpen(string title, string filter) => Ask(title);

    public string? PickFileToSave(string title, string filter, string suggestedFileName) => Ask(title);

    public string? PickFolder(string title) => Ask(title);

    private string? Ask(string title)
    {
        Asked.Add(title);
        return Answer;
    }
}
