using System.Collections.ObjectModel;
using System.Text;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Messages;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// The alarm window ("PLC messages", seed 000 §7): every alarm of the project with its state and times, acknowledge one or
/// all, the history of every transition (kept in <see cref="AlarmHistoryFile"/> when the project has a path) and its CSV
/// export. <see cref="ActiveCount"/> and <see cref="UnacknowledgedCount"/> feed the shell's status bar, window shown or not.
/// Each alarm's flag is subscribed on the line like any other value, so a flag change arrives on the UI thread.
/// The list is kept in <see cref="AlarmOrder"/>, pending alarms first; the view reports which rows it shows
/// (<see cref="ShowVisibleRows"/>) and <see cref="HiddenPendingText"/> counts the pending ones out of view.
/// A station whose flags have no good reading makes its alarms unknown (<see cref="UnknownText"/>), never "no alarms".
/// </summary>
public sealed partial class AlarmsViewModel : ObservableObject, IDisposable
{
    private readonly AlarmTracker _tracker;
    private readonly AlarmHistoryFile? _historyFile;
    private readonly IFileDialogService _files;
    private readonly string _projectName;
    private readonly TimeZoneInfo _zone;
    private readonly List<IDisposable> _subscriptions = [];
    private readonly AlarmRowViewModel[] _projectRows;
    private (int First, int Count)? _visibleRows;

    /// <param name="project">The project whose alarms are tracked.</param>
    /// <param name="projectPath">The project file, or null for a project not saved yet (history kept in memory only).</param>
    /// <param name="values">The line's values (PanelSession.Values); callbacks come on the UI thread.</param>
    /// <param name="time">Times raised, cleared and acknowledged; its local zone for display.</param>
    /// <param name="files">The save dialog of the CSV export.</param>
    /// <param name="stations">The session's stations (PanelSession.Stations), for why a station's alarms are unknown ("offline").</param>
    public AlarmsViewModel(
        PanelProject project, string? projectPath, ILineValues values, TimeProvider time, IFileDialogService files, IEnumerable<StationStatusViewModel>? stations = null)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(values);
        ArgumentNullException.ThrowIfNull(time);
        ArgumentNullException.ThrowIfNull(files);
        (_files, _projectName, _zone) = (files, project.Name, time.LocalTimeZone);
        _tracker = new AlarmTracker(project, time);
        if (projectPath is not null)
        {
            _historyFile = new AlarmHistoryFile(AlarmHistoryFile.PathFor(projectPath), time);
            var load = _historyFile.Load();
            _tracker.Restore(load.Events);
            History = new ObservableCollection<AlarmHistoryRowViewModel>(load.Events.Select(e => new AlarmHistoryRowViewModel(e, _zone)));
            (Message, IsMessageError) = (load.Message, load.Message is not null);
        }
        else
        {
            History = [];
        }

        _projectRows = [.. _tracker.Alarms.Select(a => new AlarmRowViewModel(a, time.LocalTimeZone))];
        Rows = new ObservableCollection<AlarmRowViewModel>(Ordered());
        _stations = stations;
        WatchStations();
        UpdateCounts();
        foreach (var alarm in _tracker.Alarms.ToList())
        {
            var (station, flag) = (alarm.Station, alarm.Definition.Flag);
            _subscriptions.Add(values.Subscribe(station, flag, value => Record(_tracker.Apply(station, flag, value) is { } entry ? [entry] : [])));
        }
    }

    /// <summary>
    /// Every alarm of the project in <see cref="AlarmOrder"/>: pending (active or unacknowledged) alarms first. Rows move
    /// (ObservableCollection.Move) as their state changes; the banner filters on <see cref="AlarmRowViewModel.IsPending"/>.
    /// </summary>
    public ObservableCollection<AlarmRowViewModel> Rows { get; }

    /// <summary>
    /// "3 more pending alarms below", "1 pending alarm above", "2 pending alarms above, 1 below" when pending alarms are
    /// out of the rows the view shows; null when every pending alarm is in view (or the view has not said what it shows).
    /// </summary>
    [ObservableProperty]
    public partial string? HiddenPendingText { get; private set; }

    /// <summary>
    /// The banner's one line (an HMI's alarm line): the first pending alarm in <see cref="AlarmOrder"/>; null when none is
    /// pending. One line whatever the number of alarms, so the banner never pushes the panes off a small screen.
    /// </summary>
    [ObservableProperty]
    public partial AlarmRowViewModel? MostUrgent { get; private set; }

    /// <summary>Beside <see cref="MostUrgent"/>: "and 4 more", the other pending alarms; null when there are none.</summary>
    [ObservableProperty]
    public partial string? MorePendingText { get; private set; }

    /// <summary>The first pending alarm out of view (the view scrolls it into view on request); null when none is hidden.</summary>
    [ObservableProperty]
    public partial AlarmRowViewModel? FirstHiddenPending { get; private set; }

    /// <summary>Every transition, oldest first, including those loaded from the history file; local time, as <see cref="Rows"/>.</summary>
    public ObservableCollection<AlarmHistoryRowViewModel> History { get; }

    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(Summary), nameof(ShortSummary), nameof(BannerText))]
    public partial int ActiveCount { get; private set; }

    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(Summary), nameof(ShortSummary), nameof(BannerText))]
    [NotifyCanExecuteChangedFor(nameof(AcknowledgeAllCommand))]
    public partial int UnacknowledgedCount { get; private set; }

    /// <summary>
    /// For the Alarms window: "2 alarms active, 1 unacknowledged", or "no alarms" when every flag was read; "alarms unknown"
    /// (with the counts of the last reading, "alarms unknown; when last read 1 alarm active, 1 unacknowledged") while any
    /// flag has no good reading.
    /// </summary>
    public string Summary => Describe(" alarm", " alarms");

    /// <summary>The same for the status bar, without the noun: "2 active, 1 unacknowledged".</summary>
    public string ShortSummary => Describe(string.Empty, string.Empty);

    /// <summary>
    /// The banner's line: <see cref="ShortSummary"/>, with the stations whose alarms are unknown named and why
    /// ("alarms unknown: Filler offline; when last read 1 active, 1 unacknowledged").
    /// </summary>
    public string BannerText => UnknownText is { } unknown
        ? Counts(string.Empty, string.Empty) is { } counts ? $"{unknown}; when last read {counts}" : unknown
        : ShortSummary;

    /// <summary>The latest problem with the history file or the export, or the export's confirmation; null when none.</summary>
    [ObservableProperty]
    public partial string? Message { get; private set; }

    /// <summary><see cref="Message"/> is a problem (red); false for the export's confirmation, which is never red.</summary>
    [ObservableProperty]
    public partial bool IsMessageError { get; private set; }

    public void Dispose()
    {
        _subscriptions.ForEach(s => s.Dispose());
        UnwatchStations();
    }

    /// <summary>
    /// The view shows the rows <paramref name="first"/> to <paramref name="first"/> + <paramref name="count"/> - 1 of
    /// <see cref="Rows"/> whole (scrolled, or a pane too low for all); the hidden pending alarms are counted from them.
    /// </summary>
    public void ShowVisibleRows(int first, int count)
    {
        _visibleRows = (Math.Max(first, 0), Math.Max(count, 0));
        UpdateHiddenPending();
    }

    private void UpdateHiddenPending()
    {
        if (_visibleRows is not var (first, count))
        {
            (HiddenPendingText, FirstHiddenPending) = (null, null);
            return;
        }

        var pending = Rows.Select((row, index) => (row, index)).Where(p => p.row.IsPending).ToList();
        var above = pending.Where(p => p.index < first).ToList();
        var below = pending.Where(p => p.index >= first + count).ToList();
        FirstHiddenPending = above.Concat(below).Select(p => p.row).FirstOrDefault();
        HiddenPendingText = (above.Count, below.Count) switch
        {
            (0, 0) => null,
            (0, var b) => $"{b} more pending alarm{Plural(b)} below",
            (var a, 0) => $"{a} pending alarm{Plural(a)} above",
            (var a, var b) => $"{a} pending alarm{Plural(a)} above, {b} below",
        };
    }

    private string Describe(string one, string many)
    {
        var counts = Counts(one, many);
        return UnknownText is null ? counts ?? "no alarms" : counts is null ? "alarms unknown" : "alarms unknown; when last read " + counts;
    }

    private string? Counts(string one, string many) => ActiveCount == 0 && UnacknowledgedCount == 0
        ? null
        : $"{ActiveCount}{(ActiveCount == 1 ? one : many)} active, {UnacknowledgedCount} unacknowledged";

    private static string Plural(int count) => count == 1 ? string.Empty : "s";

    private IEnumerable<AlarmRowViewModel> Ordered() =>
        _projectRows.Select((row, index) => (Row: row, Index: index))
            .Order(Comparer<(AlarmRowViewModel Row, int Index)>.Create((a, b) => AlarmOrder.Compare(a.Row.Status, a.Index, b.Row.Status, b.Index)))
            .Select(p => p.Row);

    /// <summary>Moves rows into <see cref="AlarmOrder"/>; a move, not a reset, keeps the grid's selection and scroll position.</summary>
    private void Reorder()
    {
        var target = Ordered().ToList();
        for (var i = 0; i < target.Count; i++)
        {
            var at = Rows.IndexOf(target[i]);
            if (at != i)
            {
                Rows.Move(at, i);
            }
        }
    }

    [RelayCommand(CanExecute = nameof(CanAcknowledge))]
    private void Acknowledge(AlarmRowViewModel row)
    {
        if (_tracker.Acknowledge(row.Station, row.Status.Definition.Flag) is { } entry)
        {
            Record([entry]);
        }
    }

    private static bool CanAcknowledge(AlarmRowViewModel? row) => row?.IsUnacknowledged == true;

    [RelayCommand(CanExecute = nameof(CanAcknowledgeAll))]
    private void AcknowledgeAll() => Record(_tracker.AcknowledgeAll());

    private bool CanAcknowledgeAll() => UnacknowledgedCount > 0;

    /// <summary>Shows the tracker's state: after transitions (recorded in the history), or a flag turning known or unknown.</summary>
    private void Record(IReadOnlyList<AlarmEvent> events)
    {
        for (var i = 0; i < _projectRows.Length; i++)
        {
            _projectRows[i].Update(_tracker.Alarms[i]);
        }

        Reorder();

        foreach (var entry in events)
        {
            History.Add(new AlarmHistoryRowViewModel(entry, _zone));
        }

        if (events.Count > 0 && _historyFile is not null && !_historyFile.TryAppend(events, out var error))
        {
            (Message, IsMessageError) = (error, true);
        }

        UpdateCounts();
    }

    private void UpdateCounts()
    {
        ActiveCount = _tracker.ActiveCount;
        UnacknowledgedCount = _tracker.UnacknowledgedCount;
        var pending = Rows.Count(r => r.IsPending);
        MostUrgent = pending > 0 ? Rows[0] : null;
        MorePendingText = pending > 1 ? $"and {pending - 1} more" : null;
        UpdateUnknown();
        UpdateHiddenPending();
        AcknowledgeCommand.NotifyCanExecuteChanged();
        ExportCsvCommand.NotifyCanExecuteChanged();
    }

    [RelayCommand(CanExecute = nameof(HasHistory))]
    private void ExportCsv()
    {
        var suggested = (string.IsNullOrWhiteSpace(_projectName) ? "alarms" : _projectName + " alarms") + ".csv";
        if (_files.PickFileToSave("Export alarm history", "CSV files (*.csv)|*.csv", suggested) is not { } path)
        {
            return;
        }

        try
        {
            // UTF-8 with a byte-order mark: Excel on Windows reads alarm texts with accents correctly only then.
            File.WriteAllText(path, AlarmCsv.Format(History.Select(h => h.Event)), new UTF8Encoding(encoderShouldEmitUTF8Identifier: true));
            (Message, IsMessageError) = ($"Exported {History.Count} history entries to {path} (times in UTC).", false);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or NotSupportedException)
        {
            (Message, IsMessageError) = ($"The alarm history could not be exported to {path}: {FileProblemText.Describe(ex, path, FileAction.Write)}.", true);
        }
    }

    private bool HasHistory() => History.Count > 0;
}
