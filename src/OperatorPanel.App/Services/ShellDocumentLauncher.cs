using System.ComponentModel;
using System.Diagnostics;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.App.Services;

/// <summary>Opens a file the way a double-click in Explorer does (the alarm journal's print page opens in the browser).</summary>
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
        catch (Win32Exception ex)
        {
            error = ex.Message;
            return false;
        }
    }
}
