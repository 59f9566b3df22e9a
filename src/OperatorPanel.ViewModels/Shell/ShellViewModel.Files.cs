using System.Collections.Immutable;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>New, Open, Save, Save As and Close, each asking "save changes?" before unsaved work would be lost.</summary>
public sealed partial class ShellViewModel
{
    /// <summary>At most this many problems of a corrupt file go into the message box; the log has them all.</summary>
    private const int ProblemsShown = 8;

    /// <summary>
    /// The longest the panel waits for its line when it closes: a serial port (a USB adapter's driver above all) may
    /// hang in its close, and the operator closing the panel must not wait on it.
    /// </summary>
    public static readonly TimeSpan CloseWait = TimeSpan.FromSeconds(2);

    /// <summary>
    /// For the window's Closing: asks about unsaved changes (Cancel keeps the window open: return false), then
    /// disconnects, waiting for the line at most <see cref="CloseWait"/> (a line still closing after that is left to
    /// finish on its own, and the log says so). The App cancels the first Closing, awaits this, and closes again when it
    /// returns true.
    /// </summary>
    public async Task<bool> CloseAsync()
    {
        if (!await ConfirmDiscardAsync())
        {
            return false;
        }

        var disconnect = Session.DisconnectAsync();
        if (await Task.WhenAny(disconnect, Task.Delay(CloseWait, _time)) != disconnect)
        {
            var ports = string.Join(", ", Session.Project.Stations.Select(s => s.Link.PortName).Distinct(StringComparer.OrdinalIgnoreCase));
            _logger.Warning("The line did not close within {Seconds} s ({Ports:l}); the panel closes without waiting for it", CloseWait.TotalSeconds, ports);
            await History.DisposeAsync();
            return true;
        }

        try
        {
            await disconnect;
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            // Closing goes on: the panel is leaving, and the line is as closed as it will get.
            _logger.Error(exception, "Disconnecting on close failed");
        }

        await History.DisposeAsync();
        return true;
    }

    /// <summary>Opens <paramref name="path"/> (a command-line argument, a recent file) after asking about unsaved changes.</summary>
    public async Task<bool> OpenFileAsync(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        return await ConfirmDiscardAsync() && await LoadAndReplaceAsync(path, demo: false);
    }

    [RelayCommand]
    private async Task NewAsync()
    {
        if (!await ConfirmDiscardAsync() || await _services.NewProjects.CreateAsync() is not { } project)
        {
            return;
        }

        await ReplaceAsync(project, path: null, demo: false);
        IsDirty = true;
    }

    [RelayCommand]
    private async Task OpenAsync()
    {
        if (await ConfirmDiscardAsync() && _services.Files.PickFileToOpen("Open project", ProjectFilter) is { } path)
        {
            await LoadAndReplaceAsync(path, demo: false);
        }
    }

    /// <summary>
    /// The first problems, then how many are left out, then the last one: when the loader stopped at its limit, the
    /// last line is the one saying so, and a count alone would read as the whole number.
    /// </summary>
    private static string ProblemLines(ImmutableArray<ProjectFileError> errors)
    {
        var lines = errors.Length <= ProblemsShown + 1
            ? errors.Select(e => e.ToString())
            : errors.Take(ProblemsShown).Select(e => e.ToString())
                .Append($"(and {errors.Length - ProblemsShown - 1} more)")
                .Append(errors[^1].ToString());
        return string.Join(Environment.NewLine, lines);
    }

    /// <summary>A file that does not load leaves the current project open (and connected) as it was.</summary>
    private async Task<bool> LoadAndReplaceAsync(string path, bool demo)
    {
        var result = ProjectFile.Load(path);
        if (!result.Ok)
        {
            _logger.Warning("Project {Path} not opened: {Problems}", path, string.Join("; ", result.Errors));
            await _services.Dialogs.ShowErrorAsync(
                "Project not opened",
                $"{path} is not a usable project file; the current project stays open.{Environment.NewLine}{ProblemLines(result.Errors)}");
            StatusLine.ShowError($"{Path.GetFileName(path)} not opened: {result.Errors[0]}");
            return false;
        }

        await ReplaceAsync(result.Project, demo ? null : path, demo);
        return true;
    }

    private async Task ReplaceAsync(PanelProject project, string? path, bool demo)
    {
        await Session.DisconnectAsync();
        // The path first: the Alarms window made for the new project keeps its history beside this file.
        (ProjectPath, IsDemo) = (path, demo);
        Session.Load(project);

        // A compact station with "allowStop" loads (it reads and writes as any other) but its Stop PLC can never work, and
        // a writable tag the write rules refuse can never be written: said at once, as project check says it, rather than
        // found when Generate PLC code or the write refuses.
        if (ProjectChecks.Problems(project) is [var contradiction, ..])
        {
            StatusLine.ShowError($"Opened {ProjectName}; {contradiction.Message} (File > Edit project)");
        }
        else
        {
            StatusLine.Show($"Opened {ProjectName}");
        }
    }

    /// <summary>SaveCommand; true when saved (false: cancelled or failed, the project stays unsaved).</summary>
    [RelayCommand(CanExecute = nameof(HasProject))]
    private async Task<bool> SaveAsync() => ProjectPath is { } path ? await SaveToAsync(path) : await SaveAsAsync();

    [RelayCommand(CanExecute = nameof(HasProject))]
    private async Task<bool> SaveAsAsync()
    {
        var path = _services.Files.PickFileToSave("Save project as", ProjectFilter, ProjectName + ProjectFile.Extension);
        return path is not null && await SaveToAsync(path);
    }

    /// <summary>Atomic (ProjectFile.TrySave): a failed save leaves the file on disk as it was and the project unsaved.</summary>
    private async Task<bool> SaveToAsync(string path)
    {
        if (!ProjectFile.TrySave(Session.SavedProject, path, out var error))
        {
            _logger.Warning("Saving {Path} failed: {Error}", path, error);
            await _services.Dialogs.ShowErrorAsync("Project not saved", $"{path}: {error}");
            StatusLine.ShowError($"Not saved: {error}");
            return false;
        }

        ProjectPath = path;
        Session.MarkSaved();
        StatusLine.Show($"Saved to {path}");
        return true;
    }

    /// <summary>True when the current project may go: nothing unsaved, saved now, or the operator discards it.</summary>
    private async Task<bool> ConfirmDiscardAsync()
    {
        if (!IsDirty)
        {
            return true;
        }

        return await _services.Dialogs.AskSaveChangesAsync(ProjectName) switch
        {
            SaveChangesAnswer.Save => await SaveAsync(),
            SaveChangesAnswer.Discard => true,
            SaveChangesAnswer.Cancel => false,
        };
    }
}
