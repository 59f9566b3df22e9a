using System.Collections.ObjectModel;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Journal;
using OperatorPanel.Historian.Storage;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// The alarm window ("PLC messages", seed 000 §7): every alarm of the project with its state and times, acknowledge one or
/// all, the alarm journal (<see cref="Journal"/>: every transition, kept in the project's history database when it has
/// one, searched, exported and printed there) and the alarm sound (<see cref="Annunciator"/>). <see cref="ActiveCount"/>
/// and <see cref="UnacknowledgedCount"/> feed the shell's status bar, window shown or not. Each alarm's flag is subscribed
/// on the line like any other value, so a flag change arrives on the UI thread; <see cref="StartAsync"/> first takes up
/// where the journal left off (an alarm unacknowledged at the last shutdown waits again), then subscribes.
/// The list is kept in <see cref="AlarmOrder"/>, pending alarms first; the view reports which rows it shows
/// (<see cref="ShowVisibleRows"/>) and <see cref="HiddenPendingText"/> counts the pending ones out of view.
/// A station whose flags have no good reading makes its alarms unknown (<see cref="UnknownText"/>), never "no alarms".
/// </summary>
public sealed partial class AlarmsViewModel : ObservableObject, IDisposable
{
    private readonly AlarmTracker _tracker;
    private readonly AlarmJournal? _journal;
    private readonly ILineValues _values;
    private readonly string _user;
    private readonly List<IDisposable> _subscriptions = [];
    private readonly AlarmRowViewModel[] _projectRows;
    private (int First, int Count)? _visibleRows;
    private bool _disposed;

    /// <param name="project">The project whose alarms are tracked.</param>
    /// <param name="journal">The project's alarm journal (its history database), or null for a project never saved (kept in memory only).</param>
    /// <param name="values">The line's values (PanelSession.Values); callbacks come on the UI thread.</param>
    /// <param name="time">Times raised, cleared and acknowledged; its local zone for display.</param>
    /// <param name="services">Dialogs, the sound, the print page's folder, and who acknowledges.</param>
    /// <param name="stations">The session's stations (PanelSession.Stations), for why a station's alarms are unknown ("offline").</param>
    public AlarmsViewModel(
        PanelProject project, AlarmJournal? journal, ILineValues values, TimeProvider time, AlarmServices services, IEnumerable<StationStatusViewModel>? stations = null)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(values);
        ArgumentNullException.ThrowIfNull(time);
        ArgumentNullException.ThrowIfNull(services);
        (_journal, _values, _user) = (journal, values, services.User);
        _tracker = new AlarmTracker(project, time);
        Journal = new AlarmJournalViewModel(project, journal, time, services.Files, services.Documents, services.PrintFolder);
        Annunciator = new AlarmAnnunciator(services.Sound, time, project.AlarmSound);
        _projectRows = [.. _tracker.Alarms.Select(a => new AlarmRowViewModel(a, time.LocalTimeZone))];
        Rows = new ObservableCollection<AlarmRowViewModel>(Ordered());
        _stations = stations;
        WatchStations();
        UpdateCounts();
    }

    /// <summary>The journal: search, CSV export, print.</summary>
    public AlarmJournalViewModel Journal { get; }

    /// <summary>The alarm sound and its Silence command.</summary>
    public AlarmAnnunciator Annunciator { get; }

    /// <summary>
    /// Takes up the journal's state (each alarm's entries since its last raise), shows the last day of the journal, then
    /// listens to the flags. A journal that cannot be read is reported in <see cref="Message"/> and the alarms start clear.
    /// </summary>
    public async Task StartAsync()
    {
        if (_journal is not null)
        {
            try
            {
                _tracker.Restore(await _journal.SinceLastRaiseAsync());
            }
            catch (HistoryException failure)
            {
                (Message, IsMessageError) = (failure.Message, true);
            }

            RefreshRows();
        }

        await Journal.SearchCommand.ExecuteAsync(null);
        if (_disposed)
        {
            return;
        }

        foreach (var alarm in _tracker.Alarms.ToList())
        {
            var (station, flag) = (alarm.Station, alarm.Definition.Flag);
            _subscriptions.Add(_values.Subscribe(station, flag, value => Record(_tracker.Apply(station, flag, value) is { } entry ? [entry] : [])));
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

    /// <summary>The latest problem reading the journal; null when none (the journal's own messages are in <see cref="Journal"/>).</summary>
    [ObservableProperty]
    public partial string? Message { get; private set; }

    /// <summary><see cref="Message"/> is a problem (red); the window's messages are all problems, the journal's are not.</summary>
    [ObservableProperty]
    public partial bool IsMessageError { get; private set; }

    public void Dispose()
    {
        _disposed = true;
        _subscriptions.ForEach(s => s.Dispose());
        UnwatchStations();
        Annunciator.Dispose();
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
        RefreshRows();
        foreach (var entry in events)
        {
            // Who acknowledged: the panel's user; a raise or a clear is the PLC's doing.
            var user = entry.Transition == AlarmTransition.Acknowledged ? _user : null;
            _journal?.Append(entry, user);
            Journal.Add(entry, user);
        }
    }

    private void RefreshRows()
    {
        for (var i = 0; i < _projectRows.Length; i++)
        {
            _projectRows[i].Update(_tracker.Alarms[i]);
        }

        Reorder();
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
        Annunciator.Update(_tracker.Alarms);
    }
}
