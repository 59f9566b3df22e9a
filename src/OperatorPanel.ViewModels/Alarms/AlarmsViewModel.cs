using System.Collections.ObjectModel;
using System.Text;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Mvvm;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Values;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// The alarm window ("PLC messages", seed 000 §7): every alarm of the project with its state and times, acknowledge one or
/// all, the history of every transition (kept in <see cref="AlarmHistoryFile"/> when the project has a path) and its CSV
/// export. <see cref="ActiveCount"/> and <see cref="UnacknowledgedCount"/> feed the shell's status bar, window shown or not.
/// Values arrive on the polling thread and are applied on the dispatcher's.
/// </summary>
public sealed class AlarmsViewModel : ObservableObject, IDisposable
{
    private readonly AlarmTracker _tracker;
    private readonly AlarmHistoryFile? _historyFile;
    private readonly IUiDispatcher _dispatcher;
    private readonly IFileDialogService _files;
    private readonly string _projectName;
    private readonly IDisposable _subscription;
    private int _activeCount;
    private int _unacknowledgedCount;
    private string? _message;

    /// <param name="project">The project whose alarms are tracked.</param>
    /// <param name="projectPath">The project file, or null for a project not saved yet (history kept in memory only).</param>
    /// <param name="values">Value changes from the polling engine (see <see cref="ValueChangeRelay"/>).</param>
    /// <param name="time">Times raised, cleared and acknowledged; its local zone for display.</param>
    /// <param name="dispatcher">Where bound properties change.</param>
    /// <param name="files">The save dialog of the CSV export.</param>
    public AlarmsViewModel(
        PanelProject project, string? projectPath, IValueChangeSource values, TimeProvider time, IUiDispatcher dispatcher, IFileDialogService files)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(values);
        ArgumentNullException.ThrowIfNull(time);
        ArgumentNullException.ThrowIfNull(dispatcher);
        ArgumentNullException.ThrowIfNull(files);
        (_dispatcher, _files, _projectName) = (dispatcher, files, project.Name);
        _tracker = new AlarmTracker(project, time);
        if (projectPath is not null)
        {
            _historyFile = new AlarmHistoryFile(AlarmHistoryFile.PathFor(projectPath), time);
            var load = _historyFile.Load();
            _tracker.Restore(load.Events);
            History = new ObservableCollection<AlarmEvent>(load.Events);
            _message = load.Message;
        }
        else
        {
            History = [];
        }

        Rows = new ObservableCollection<AlarmRowViewModel>(_tracker.Alarms.Select(a => new AlarmRowViewModel(a, time.LocalTimeZone)));
        AcknowledgeCommand = new RelayCommand<AlarmRowViewModel>(Acknowledge, row => row.IsUnacknowledged);
        AcknowledgeAllCommand = new RelayCommand(() => Record(_tracker.AcknowledgeAll()), () => UnacknowledgedCount > 0);
        ExportCsvCommand = new RelayCommand(ExportCsv, () => History.Count > 0);
        UpdateCounts();
        _subscription = values.Subscribe(changes => _dispatcher.Post(() => Record(_tracker.Apply(changes))));
    }

    /// <summary>Every alarm of the project, in project order; the view filters on <see cref="AlarmRowViewModel.IsPending"/>.</summary>
    public ObservableCollection<AlarmRowViewModel> Rows { get; }

    /// <summary>Every transition, oldest first, including those loaded from the history file.</summary>
    public ObservableCollection<AlarmEvent> History { get; }

    public RelayCommand<AlarmRowViewModel> AcknowledgeCommand { get; }

    public RelayCommand AcknowledgeAllCommand { get; }

    public RelayCommand ExportCsvCommand { get; }

    public int ActiveCount { get => _activeCount; private set => SetProperty(ref _activeCount, value); }

    public int UnacknowledgedCount { get => _unacknowledgedCount; private set => SetProperty(ref _unacknowledgedCount, value); }

    /// <summary>For the status bar: "2 alarms active, 1 unacknowledged", or "no alarms".</summary>
    public string Summary => ActiveCount == 0 && UnacknowledgedCount == 0
        ? "no alarms"
        : $"{ActiveCount} alarm{(ActiveCount == 1 ? string.Empty : "s")} active, {UnacknowledgedCount} unacknowledged";

    /// <summary>The latest problem with the history file or the export, or the export's confirmation; null when none.</summary>
    public string? Message { get => _message; private set => SetProperty(ref _message, value); }

    public void Dispose() => _subscription.Dispose();

    private void Acknowledge(AlarmRowViewModel row)
    {
        if (_tracker.Acknowledge(row.Station, row.Status.Definition.Flag) is { } entry)
        {
            Record([entry]);
        }
    }

    private void Record(IReadOnlyList<AlarmEvent> events)
    {
        if (events.Count == 0)
        {
            return;
        }

        for (var i = 0; i < Rows.Count; i++)
        {
            Rows[i].Update(_tracker.Alarms[i]);
        }

        foreach (var entry in events)
        {
            History.Add(entry);
        }

        if (_historyFile is not null && !_historyFile.TryAppend(events, out var error))
        {
            Message = error;
        }

        UpdateCounts();
    }

    private void UpdateCounts()
    {
        ActiveCount = _tracker.ActiveCount;
        UnacknowledgedCount = _tracker.UnacknowledgedCount;
        OnPropertyChanged(nameof(Summary));
        AcknowledgeCommand.NotifyCanExecuteChanged();
        AcknowledgeAllCommand.NotifyCanExecuteChanged();
        ExportCsvCommand.NotifyCanExecuteChanged();
    }

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
            File.WriteAllText(path, AlarmCsv.Format(History), new UTF8Encoding(encoderShouldEmitUTF8Identifier: true));
            Message = $"Exported {History.Count} history entries to {path}.";
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or NotSupportedException)
        {
            Message = $"The alarm history could not be exported to {path}: {ex.Message}";
        }
    }
}
