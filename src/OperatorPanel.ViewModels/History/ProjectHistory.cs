using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian;
using OperatorPanel.Historian.Recording;
using OperatorPanel.Historian.Storage;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;
using Serilog;

namespace OperatorPanel.ViewModels.History;

/// <summary>
/// The open project's historian: opened when a project with a file (or the demo) is loaded or saved, kept across edits
/// of the same file, closed when another project comes. The session's values are recorded from the moment the project is
/// loaded (before connecting: the first cycle is in the history) and its writes and STOPs go to the audit. A project
/// never saved has no history. <see cref="Problem"/> says when the database takes no writes.
/// </summary>
public sealed partial class ProjectHistory : ObservableObject, IAsyncDisposable
{
    private readonly PanelSession _session;
    private readonly HistoryFolder? _folder;
    private readonly IUiDispatcher _dispatcher;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;
    private readonly List<Task> _closing = [];
    private IDisposable? _recording;
    private IReadOnlyList<RecordedTag> _recorded = [];

    /// <param name="session">Its values are recorded; its audit trail is set here.</param>
    /// <param name="folder">Where the databases are; null: no history at all (tests that do not look at it).</param>
    /// <param name="dispatcher">Problems are reported on the UI thread.</param>
    /// <param name="time">The historian's clock.</param>
    /// <param name="logger">The historian logs its problems here once.</param>
    public ProjectHistory(PanelSession session, HistoryFolder? folder, IUiDispatcher dispatcher, TimeProvider time, ILogger logger)
    {
        (_session, _folder, _dispatcher, _time, _logger) = (session, folder, dispatcher, time, logger);
    }

    /// <summary>The current project's historian; null for a project without a file.</summary>
    [ObservableProperty]
    public partial Historian.Historian? Current { get; private set; }

    /// <summary>
    /// Done when the current historian has taken in the project's old alarm history file (once per file, AlarmJournal.ImportOnceAsync):
    /// the alarm window restores from the journal after it.
    /// </summary>
    public Task Ready { get; private set; } = Task.CompletedTask;

    /// <summary>Why history is not being recorded now, in the operator's words; null while all is well.</summary>
    [ObservableProperty]
    public partial string? Problem { get; private set; }

    /// <summary>
    /// Follows the session's project: the historian of <paramref name="path"/> (the demo's own for <paramref name="demo"/>),
    /// reopened only when the file or the history settings changed, and the recording restarted for the project as it is now.
    /// </summary>
    public void Follow(PanelProject project, string? path, bool demo)
    {
        ArgumentNullException.ThrowIfNull(project);
        var database = path is not null && _folder is not null ? _folder.DatabaseFor(path, demo) : null;
        var tags = project.History.Enabled ? RecordedTag.Of(project) : [];
        if (Current is { } same && same.DatabasePath == database && same.Settings == project.History && _recording is not null && tags.SequenceEqual(_recorded))
        {
            // Saved, or edited in what is not recorded (alarm texts, descriptions): the recording goes on as it is.
            return;
        }

        _recording?.Dispose();
        _recording = null;
        if (Current is { } open && (open.DatabasePath != database || open.Settings != project.History))
        {
            Close(open);
        }

        if (database is not null && Current is null)
        {
            var historian = Historian.Historian.Open(database, project, _time, _logger, "panel");
            historian.ProblemChanged += OnProblemChanged;
            Current = historian;
            Ready = demo ? Task.CompletedTask : ImportAsync(historian, path!);
        }

        _session.Audit = Current?.Audit ?? AuditTrail.None;
        _recording = Current?.RecordLine(project, _session.Values, _session.StatusOf);
        _recorded = tags;
        Problem = Current?.Problem;
    }

    /// <summary>Stops recording and starts closing the database (storing what is queued) in the background.</summary>
    public void Stop()
    {
        _recording?.Dispose();
        _recording = null;
        _session.Audit = AuditTrail.None;
        if (Current is { } open)
        {
            Close(open);
        }
    }

    /// <summary>Stops recording and closes the database after storing what is queued.</summary>
    public async ValueTask DisposeAsync()
    {
        Stop();
        await Task.WhenAll(_closing);
    }

    private async Task ImportAsync(Historian.Historian historian, string projectPath)
    {
        try
        {
            var (imported, message) = await historian.Journal.ImportOnceAsync(projectPath, _time);
            if (imported > 0 || message is not null)
            {
                _logger.Information("Alarm history {File} imported into the journal: {Count} entries. {Message}", AlarmHistoryFile.PathFor(projectPath), imported, message);
            }
        }
        catch (HistoryException failure)
        {
            _logger.Warning("Alarm history {File} not imported: {Reason}", AlarmHistoryFile.PathFor(projectPath), failure.Message);
        }
    }

    private void Close(Historian.Historian historian)
    {
        historian.ProblemChanged -= OnProblemChanged;
        Current = null;
        // Closing stores what is queued: in the background, so loading the next project never waits for the disk.
        _closing.Add(historian.DisposeAsync().AsTask());
    }

    private void OnProblemChanged(object? sender, EventArgs e) =>
        _dispatcher.Post(() => Problem = ReferenceEquals(sender, Current) ? Current?.Problem : Problem);
}
