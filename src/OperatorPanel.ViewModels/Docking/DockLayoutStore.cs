using System.Diagnostics.CodeAnalysis;
using System.Text;
using System.Text.Json;
using System.Text.Json.Serialization;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// Reads and writes the per-user layout file (JSON). A missing file is the default layout; an unreadable or corrupt
/// one is the default layout plus a message, never an exception: a layout is a convenience, not data to lose sleep over.
/// </summary>
public static class DockLayoutStore
{
    /// <summary>A layout file is a few hundred bytes; anything far larger is not ours.</summary>
    private const long MaxBytes = 64 * 1024;

    private static readonly JsonSerializerOptions Json = new()
    {
        WriteIndented = true,
        Converters = { new JsonStringEnumConverter() },
    };

    public static DockLayout Load(string path, out string? message)
    {
        message = null;
        if (!File.Exists(path))
        {
            return DockLayout.Default;
        }

        if (!AtomicFile.TryReadAll(path, MaxBytes, out var bytes, out var error))
        {
            message = $"Window layout not restored ({path}): {error}. The default layout is used.";
            return DockLayout.Default;
        }

        try
        {
            var panes = JsonSerializer.Deserialize<PaneLayout[]>(bytes, Json);
            if (panes is null)
            {
                message = $"Window layout not restored ({path}): the file is empty. The default layout is used.";
                return DockLayout.Default;
            }

            return new DockLayout([.. panes]).Normalized();
        }
        catch (JsonException ex)
        {
            message = $"Window layout not restored ({path}): {ex.Message} The default layout is used.";
            return DockLayout.Default;
        }
    }

    public static bool TrySave(DockLayout layout, string path, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(layout);
        var folder = Path.GetDirectoryName(Path.GetFullPath(path));
        if (folder is not null)
        {
            try
            {
                Directory.CreateDirectory(folder);
            }
            catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
            {
                error = "cannot create the folder: " + ex.Message;
                return false;
            }
        }

        var text = JsonSerializer.Serialize(layout.Panes.ToArray(), Json);
        return AtomicFile.TryWrite(path, Encoding.UTF8.GetBytes(text), out error);
    }
}
