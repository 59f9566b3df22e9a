using System.IO;
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

    /// <summary>
    /// A folder through the save dialog (the operator picks where the first file goes): the folder dialog of newer WPF
    /// versions is not in the reference assemblies the compile check uses, and this works on every Windows.
    /// </summary>
    public string? PickFolder(string title)
    {
        var dialog = new SaveFileDialog { Title = title, FileName = "Save here", Filter = "Folder|*.folder", OverwritePrompt = false, CheckPathExists = true };
        return dialog.ShowDialog() == true ? Path.GetDirectoryName(dialog.FileName) : null;
    }
}
