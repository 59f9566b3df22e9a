using System.IO;
using System.Text;
using System.Text.Json;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Session;
using Serilog;

namespace OperatorPanel.App.Services;

/// <summary>The operator's per-user settings (confirm writes, large display) in a small JSON file; a bad file means defaults.</summary>
public sealed class PanelOptionsStore(string path, ILogger log)
{
    private sealed record Saved(bool ConfirmWrites, bool LargeDisplay);

    public PanelOptions Load()
    {
        var options = new PanelOptions();
        if (!File.Exists(path))
        {
            return options;
        }

        try
        {
            var saved = JsonSerializer.Deserialize<Saved>(File.ReadAllText(path));
            if (saved is not null)
            {
                (options.ConfirmWrites, options.LargeDisplay) = (saved.ConfirmWrites, saved.LargeDisplay);
            }
        }
        catch (Exception ex) when (ex is JsonException or IOException or UnauthorizedAccessException)
        {
            log.Warning("Settings {Path} not read, defaults used: {Reason}", path, ex.Message);
        }

        return options;
    }

    public void Save(PanelOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        Directory.CreateDirectory(Path.GetDirectoryName(path)!);
        var json = JsonSerializer.Serialize(new Saved(options.ConfirmWrites, options.LargeDisplay));
        if (!AtomicFile.TryWrite(path, Encoding.UTF8.GetBytes(json), out var error))
        {
            log.Warning("Settings {Path} not saved: {Reason}", path, error);
        }
    }
}
