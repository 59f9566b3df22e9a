using System.ComponentModel;
using System.Diagnostics;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.App.Services;

/// <summary>Opens a document with the program Windows associates with its extension (README.txt: the text editor).</summary>
public sealed class ShellDocumentLauncher : IDocumentLauncher
{
    public bool TryOpen(string path, out string? error)
    {
        try
        {
            using var process = Process.Start(new ProcessStartInfo(path) { UseShellExecute = true });
            error = null;
            return true;
        }
        catch (Exception ex) when (ex is Win32Exception or InvalidOperationException or System.IO.FileNotFoundException)
        {
            error = ex.Message;
            return false;
        }
    }
}
