using Microsoft.Win32;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.App.Services;

/// <summary>The common Windows file dialogs.</summary>
public sealed class WpfFileDialogService : IFileDialogService
{
    public string? PickFileToOpen(string title, string filter)
    {
        var dialog = new OpenFileDialog { Title = title, Filter = filter, CheckFileExists = true };
        return dialog.ShowDialog() == true ? dialog.FileName : null;
    }

    public string? PickFileToSave(string title, string filter, string suggestedFileName)
    {
        var dialog = new SaveFileDialog { Title = title, Filter = filter, FileName = suggestedFileName, OverwritePrompt = true };
        return dialog.ShowDialog() == true ? dialog.FileName : null;
    }

    public string? PickFolder(string title)
    {
        var dialog = new OpenFolderDialog { Title = title };
        return dialog.ShowDialog() == true ? dialog.FolderName : null;
    }
}
