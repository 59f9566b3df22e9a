using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Audit;
using OperatorPanel.Historian.Journal;
using OperatorPanel.Historian.Reading;
using OperatorPanel.Historian.Recording;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.Historian;

/// <summary>
/// One project's history database (docs/historian.md): its one background writer, what records into it (the line's
/// values through <see cref="RecordLine"/>, the alarm journal, the audit of writes and STOP) and what reads it (trends,
/// <c>opanel history</c>, the journal's search). Opening never fails: a database that cannot be written is reported in
/// <see cref="Problem"/> and the panel goes on without history.
/// </summary>
public sealed class Historian : IAsyncDisposable
{
    private readonly HistoryWriter _writer;
    private readonly TimeProvider _time;

    private Historian(string path, PanelProject project, TimeProvider time, ILogger logger, string source, WriterTuning? tuning)
    {
        _time = time;
        Settings = project.History;
        _writer = new HistoryWriter(path, project.History, time, logger.ForContext<Historian>(), source, tuning);
        _writer.ProblemChanged += (_, _) => ProblemChanged?.Invoke(this, EventArgs.Empty);
        Journal = new AlarmJournal(path, _writer);
        Audit = new AuditTable(_writer);
        Reader = new HistoryReader(path);
    }

    public string DatabasePath => _writer.Path;

    public HistorySettings Settings { get; }

    /// <summary>Why history is not being stored now (locked, disk full...); null while all is well.</summary>
    public string? Problem => _writer.Problem;

    /// <summary>Raised on the writer's thread when <see cref="Problem"/> changes.</summary>
    public event EventHandler? ProblemChanged;

    /// <summary>Rows dropped because the database took no writes for too long.</summary>
    public long Lost => _writer.Lost;

    public long Written => _writer.Written;

    public AlarmJournal Journal { get; }

    /// <summary>Where the panel's writes and STOPs are recorded, intent and outcome.</summary>
    public IAuditTrail Audit { get; }

    public HistoryReader Reader { get; }

    /// <summary>Opens (creating when missing) the database at <paramref name="path"/> for <paramref name="project"/>.</summary>
    /// <param name="path">The database file, usually <see cref="HistoryFolder.DatabaseFor"/>.</param>
    /// <param name="project">Its history settings (retention) apply.</param>
    /// <param name="time">Timestamps, the writer's period, the periodic samples.</param>
    /// <param name="logger">Problems are logged once, recovery once.</param>
    /// <param name="source">Who records ("panel", "opanel watch"), kept with each recording session.</param>
    public static Historian Open(string path, PanelProject project, TimeProvider? time = null, ILogger? logger = null, string source = "panel")
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(path);
        ArgumentNullException.ThrowIfNull(project);
        return new Historian(path, project, time ?? TimeProvider.System, logger ?? Logger.None, source, null);
    }

    internal static Historian Open(string path, PanelProject project, TimeProvider time, WriterTuning tuning) =>
        new(path, project, time, Logger.None, "test", tuning);

    /// <summary>
    /// Records the project's values from <paramref name="values"/> (one subscription per value) and each station's state
    /// from <paramref name="statusOf"/>, until the result is disposed. Nothing is recorded when the project turned history off.
    /// </summary>
    public IDisposable RecordLine(PanelProject project, ILineValues values, Func<Station, StationStatus?> statusOf)
    {
        var recorder = new HistoryRecorder(project, _writer, _time);
        var feed = new LineFeed(recorder, values, statusOf, _time);
        return new Recording(recorder, feed);
    }

    /// <summary>Completes when everything recorded so far is in the database (or failed to get there: see <see cref="Problem"/>).</summary>
    public Task FlushAsync() => _writer.FlushAsync();

    /// <summary>Stores what is queued, closes the recording session and the database.</summary>
    public ValueTask DisposeAsync() => _writer.DisposeAsync();

    private sealed class Recording(HistoryRecorder recorder, LineFeed feed) : IDisposable
    {
        public void Dispose()
        {
            feed.Dispose();
            recorder.Dispose();
        }
    }
}
