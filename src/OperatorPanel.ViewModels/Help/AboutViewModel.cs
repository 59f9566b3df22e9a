using System.Reflection;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Help;

/// <summary>Help > About: the product, its version (the one the MSI installed) and the README installed beside it.</summary>
public sealed partial class AboutViewModel : ObservableObject
{
    private readonly IDocumentLauncher? _launcher;

    /// <param name="readmePath">The README the installer puts beside the program.</param>
    /// <param name="launcher">Opens it; null: the path is shown but cannot be opened from here.</param>
    public AboutViewModel(string readmePath, IDocumentLauncher? launcher)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(readmePath);
        (ReadmePath, _launcher) = (readmePath, launcher);
    }

    public string ProductName { get; } = "Operator Panel for Siemens S7-200";

    /// <summary>"Version 0.1.0": the product version (Directory.Build.props), shared by every assembly and the MSI.</summary>
    public string VersionText { get; } = $"Version {Version}";

    public string ReadmePath { get; }

    /// <summary>Why the README did not open; null until then.</summary>
    [ObservableProperty]
    public partial string? Message { get; private set; }

    /// <summary>The product version without the build's source revision ("0.1.0", not "0.1.0+3fa2...").</summary>
    public static string Version
    {
        get
        {
            var assembly = typeof(AboutViewModel).Assembly;
            var informational = assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion;
            return informational?.Split('+')[0] ?? assembly.GetName().Version?.ToString(3) ?? "unknown";
        }
    }

    [RelayCommand]
    private void OpenReadme()
    {
        if (!File.Exists(ReadmePath))
        {
            Message = $"{ReadmePath} is missing; reinstall the panel to get it back.";
        }
        else if (_launcher is null)
        {
            Message = $"Open {ReadmePath} with a text editor.";
        }
        else if (!_launcher.TryOpen(ReadmePath, out var error))
        {
            Message = $"{ReadmePath} could not be opened: {error}";
        }
        else
        {
            Message = null;
        }
    }
}
