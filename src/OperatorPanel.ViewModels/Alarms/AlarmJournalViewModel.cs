using System.Collections.ObjectModel;
using System.Text;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Journal;
using OperatorPanel.Historian.Storage;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// The alarm journal in the Alarms window: search by time range, station, class and text; export what is found to CSV;
/// print it (an HTML page opened in the browser). Reads the project's history database; a project never saved keeps
/// this session's entries in memory. New entries that match an open-ended search are added as they happen.
/// </summary>
public sealed partial class AlarmJournalViewModel : ObservableObject
{
    public const string AllStations = "All stations";
    public const string AllClasses = "All classes";
    public const int MaxShown = JournalFilter.DefaultLimit;

    private readonly AlarmJournal? _journal;
    private readonly PanelProject _project;
    private readonly TimeProvider _time;
    private readonly IFileDialogService _files;
    private readonly IDocumentLauncher? _documents;
    private readonly string _printFolder;
    private readonly List<JournalEntry> _memory = [];
    private JournalFilter _shown = JournalFilter.All;

    internal AlarmJournalViewModel(PanelProject project, AlarmJournal? journal, TimeProvider time, IFileDialogService files, IDocumentLauncher? documents, string printFolder)
    {
        (_project, _journal, _time, _files, _documents, _printFolder) = (project, journal, time, files, documents, printFolder);
        Stations = [AllStations, .. project.Stations.Select(s => s.Name)];
        Classes = [AllClasses, .. Enum.GetNames<AlarmClass>()];
        SelectedStation = AllStations;
        SelectedClass = AllClasses;
        Range = JournalRange.Day;
    }

    /// <summary>The entries found, oldest first, at most <see cref="MaxShown"/> (the newest); local time, as the alarm table.</summary>
    public ObservableCollection<AlarmHistoryRowViewModel> Entries { get; } = [];

    public IReadOnlyList<string> Stations { get; }

    public IReadOnlyList<string> Classes { get; }

    public IReadOnlyList<JournalRange> Ranges { get; } = Enum.GetValues<JournalRange>();

    [ObservableProperty]
    public partial string SelectedStation { get; set; }

    [ObservableProperty]
    public partial string SelectedClass { get; set; }

    [ObservableProperty]
    public partial JournalRange Range { get; set; }

    /// <summary>With <see cref="JournalRange.Custom"/>: the start, in the panel's local time.</summary>
    [ObservableProperty]
    public partial DateTime? CustomFrom { get; set; }

    /// <summary>With <see cref="JournalRange.Custom"/>: the end, local time; empty: up to now.</summary>
    [ObservableProperty]
    public partial DateTime? CustomTo { get; set; }

    /// <summary>Part of the alarm text or the station's name.</summary>
    [ObservableProperty]
    public partial string Text { get; set; } = string.Empty;

    /// <summary>What was found or done, or what went wrong; null before the first search.</summary>
    [ObservableProperty]
    public partial string? Message { get; private set; }

    /// <summary><see cref="Message"/> is a problem (red); false for what was found or exported, which is never red.</summary>
    [ObservableProperty]
    public partial bool IsMessageError { get; private set; }

    /// <summary>A new transition: kept, and shown when the current search would find it.</summary>
    internal void Add(AlarmEvent entry, string? user)
    {
        var added = new JournalEntry(_memory.Count + 1, entry, user);
        if (_journal is null)
        {
            _memory.Add(added);
        }

        if (Matches(_shown, added) && _shown.To is null)
        {
            Entries.Add(new AlarmHistoryRowViewModel(added, _time.LocalTimeZone));
            ExportCsvCommand.NotifyCanExecuteChanged();
            PrintCommand.NotifyCanExecuteChanged();
        }
    }

    [RelayCommand]
    private async Task SearchAsync()
    {
        var filter = Filter();
        IReadOnlyList<JournalEntry> found;
        try
        {
            found = _journal is null ? [.. _memory.Where(e => Matches(filter, e)).TakeLast(filter.Limit)] : await _journal.SearchAsync(filter);
        }
        catch (HistoryException failure)
        {
            (Message, IsMessageError) = (failure.Message, true);
            return;
        }

        _shown = filter;
        Entries.Clear();
        foreach (var entry in found)
        {
            Entries.Add(new AlarmHistoryRowViewModel(entry, _time.LocalTimeZone));
        }

        IsMessageError = false;
        Message = $"{found.Count} entr{(found.Count == 1 ? "y" : "ies")}: {Describe(filter)}{(found.Count >= filter.Limit ? $" (the newest {filter.Limit})" : string.Empty)}";
        ExportCsvCommand.NotifyCanExecuteChanged();
        PrintCommand.NotifyCanExecuteChanged();
    }

    [RelayCommand(CanExecute = nameof(HasEntries))]
    private void ExportCsv()
    {
        var suggested = (string.IsNullOrWhiteSpace(_project.Name) ? "alarms" : _project.Name + " alarms") + ".csv";
        if (_files.PickFileToSave("Export alarm journal", "CSV files (*.csv)|*.csv", suggested) is not { } path)
        {
            return;
        }

        // UTF-8 with a byte-order mark: Excel on Windows reads alarm texts with accents correctly only then.
        (Message, IsMessageError) = Write(path, JournalCsv.Format(Entries.Select(e => e.Entry)), new UTF8Encoding(encoderShouldEmitUTF8Identifier: true)) is { } error
            ? ($"The alarm journal could not be exported to {path}: {error}", true)
            : ($"Exported {Entries.Count} journal entries to {path} (times in UTC).", false);
    }

    /// <summary>Writes the entries found as an HTML page and opens it in the browser, whose Print prints it.</summary>
    [RelayCommand(CanExecute = nameof(HasEntries))]
    private void Print()
    {
        var title = $"Alarm journal: {(_project.Name.Length > 0 ? _project.Name : "untitled project")}";
        var html = JournalHtml.Format(title, Describe(_shown), _time.GetUtcNow(), _time.LocalTimeZone, Entries.Select(e => e.Entry));
        var path = Path.Combine(_printFolder, $"alarm-journal-{_time.GetLocalNow():yyyyMMdd-HHmmss}.html");
        (Message, IsMessageError) = Write(path, html, new UTF8Encoding(false)) is { } error
            ? ($"The print page could not be written to {path}: {error}", true)
            : _documents is null || !_documents.TryOpen(path, out _)
                ? ($"The print page is {path}; open it in a browser to print it.", false)
                : ($"Opened {path} to print ({Entries.Count} entries).", false);
    }

    private bool HasEntries() => Entries.Count > 0;

    private JournalFilter Filter()
    {
        var now = _time.GetUtcNow();
        DateTimeOffset? Local(DateTime? at) => at is { } t ? new DateTimeOffset(DateTime.SpecifyKind(t, DateTimeKind.Unspecified), _time.LocalTimeZone.GetUtcOffset(t)) : null;
        var (from, to) = Range switch
        {
            JournalRange.LastHour => (now.AddHours(-1), (DateTimeOffset?)null),
            JournalRange.Shift => (now.AddHours(-8), null),
            JournalRange.Day => (now.AddDays(-1), null),
            JournalRange.Week => (now.AddDays(-7), null),
            JournalRange.All => ((DateTimeOffset?)null, null),
            JournalRange.Custom => (Local(CustomFrom), Local(CustomTo)),
        };
        var station = _project.Stations.FirstOrDefault(s => s.Name == SelectedStation)?.Address;
        AlarmClass? alarmClass = Enum.TryParse<AlarmClass>(SelectedClass, out var c) ? c : null;
        return new JournalFilter(from, to, station, alarmClass, string.IsNullOrWhiteSpace(Text) ? null : Text.Trim());
    }

    /// <summary>"last 24 hours, all stations, all classes, text containing 'jam'".</summary>
    private string Describe(JournalFilter filter)
    {
        var range = Range switch
        {
            JournalRange.LastHour => "the last hour",
            JournalRange.Shift => "the last 8 hours",
            JournalRange.Day => "the last 24 hours",
            JournalRange.Week => "the last 7 days",
            JournalRange.All => "all times",
            JournalRange.Custom => $"{filter.From?.ToLocalTime():yyyy-MM-dd HH:mm} to {(filter.To is { } to ? to.ToLocalTime().ToString("yyyy-MM-dd HH:mm", System.Globalization.CultureInfo.InvariantCulture) : "now")}",
        };
        var station = filter.Station is null ? "all stations" : SelectedStation;
        var alarmClass = filter.Class is { } c ? AlarmCsv.Words(c.ToString()) + " alarms" : "all classes";
        return $"{range}, {station}, {alarmClass}{(filter.Text is { } t ? $", text containing '{t}'" : string.Empty)}";
    }

    private static bool Matches(JournalFilter filter, JournalEntry entry)
    {
        var e = entry.Event;
        return (filter.From is not { } from || e.At >= from) && (filter.To is not { } to || e.At <= to)
            && (filter.Station is not { } station || e.Station == station) && (filter.Class is not { } c || e.Class == c)
            && (filter.Text is not { } text || e.Text.Contains(text, StringComparison.OrdinalIgnoreCase) || e.StationName.Contains(text, StringComparison.OrdinalIgnoreCase));
    }

    private static string? Write(string path, string text, Encoding encoding)
    {
        try
        {
            if (Path.GetDirectoryName(path) is { Length: > 0 } folder)
            {
                Directory.CreateDirectory(folder);
            }

            File.WriteAllText(path, text, encoding);
            return null;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or NotSupportedException)
        {
            return ex.Message;
        }
    }
}
