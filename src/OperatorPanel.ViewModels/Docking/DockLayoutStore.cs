using System.Diagnostics.CodeAnalysis;
using System.Text;
using System.Text.Json;
using System.Text.Json.Serialization;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Docking;

/// <summary>
/// Reads and writes the per-user layout file (JSON: the main window's place and the panes by content id). A missing
/// file is the default layout; an unreadable or corrupt one is the default layout plus a message, never an exception: a
/// layout is a convenience, not data to lose sleep over. Files of the first version (a bare array of panes keyed by
/// "Id") are still read.
/// </summary>
public static class DockLayoutStore
{
    /// <summary>A layout file is a few hundred bytes; anything far larger is not ours.</summary>
    private const long MaxBytes = 64 * 1024;

    private static readonly JsonSerializerOptions Json = new()
    {
        WriteIndented = true,
        // A window position the system chose is saved as NaN ("let the system place it").
        NumberHandling = JsonNumberHandling.AllowNamedFloatingPointLiterals,
        Converters = { new JsonStringEnumConverter() },
    };

    public static DockLayout Load(string path, DockLayout defaults, out string? message)
    {
        ArgumentNullException.ThrowIfNull(defaults);
        message = null;
        if (!File.Exists(path))
        {
            return defaults;
        }

        if (!AtomicFile.TryReadAll(path, MaxBytes, out var bytes, out var error))
        {
            message = $"Window layout not restored ({path}): {error}. The default layout is used.";
            return defaults;
        }

        try
        {
            var layout = Parse(bytes);
            if (layout is null)
            {
                message = $"Window layout not restored ({path}): the file is empty. The default layout is used.";
                return defaults;
            }

            return layout.Normalized(defaults);
        }
        catch (JsonException ex)
        {
            // Our words, not the parser's: where the file stops being a layout.
            var at = ex.LineNumber is { } line ? $" at line {line + 1}, character {(ex.BytePositionInLine ?? 0) + 1}" : string.Empty;
            message = $"Window layout not restored ({path}): the file is not a layout this panel wrote (unreadable{at}). The default layout is used.";
            return defaults;
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

        var text = JsonSerializer.Serialize(new SavedLayout(layout.Window, [.. layout.Panes]), Json);
        return AtomicFile.TryWrite(path, Encoding.UTF8.GetBytes(text), out error);
    }

    private static DockLayout? Parse(byte[] bytes)
    {
        using var document = JsonDocument.Parse(bytes);
        if (document.RootElement.ValueKind == JsonValueKind.Array)
        {
            var first = document.RootElement.Deserialize<FirstVersionPane[]>(Json);
            return first is null ? null : new DockLayout([.. first.Where(p => p.Id is not null).Select(p => new PaneLayout(p.Id, p.IsVisible, p.Placement, p.DockedSize, p.Float, p.Order))]);
        }

        var saved = document.RootElement.Deserialize<SavedLayout>(Json);
        return saved is null ? null : new DockLayout([.. (saved.Panes ?? []).Where(p => p.ContentId is not null)]) { Window = saved.Window };
    }

    private sealed record SavedLayout(WindowPlacement? Window, PaneLayout[]? Panes);

    /// <summary>A pane as the first version saved it, keyed by its DockPaneId name (the same names the content ids kept).</summary>
    private sealed record FirstVersionPane(string Id, bool IsVisible, DockPlacement Placement, double DockedSize, FloatBounds Float, int Order);
}
