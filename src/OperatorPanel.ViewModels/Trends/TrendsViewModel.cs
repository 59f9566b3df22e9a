using System.Collections.ObjectModel;
using System.ComponentModel;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Reading;
using OperatorPanel.Historian.Recording;
using OperatorPanel.Historian.Storage;
using OperatorPanel.ViewModels.History;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Trends;

/// <summary>
/// The Trends window: pick tags from the project's recorded values, watch them live (the window scrolls with time, redrawn
/// every second) or look back over the history (last hour, shift, day, a custom range), zoom and pan, and read each tag's
/// value and quality at a cursor. Everything comes from the project's history database (what the panel recorded, with its
/// gaps) and goes out as one <see cref="TrendPlot"/> the App draws. A project without history shows nothing but says why.
/// </summary>
public sealed partial class TrendsViewModel : ObservableObject, IDisposable
{
    public static readonly TimeSpan RefreshPeriod = TimeSpan.FromSeconds(1);
    public static readonly TimeSpan DefaultLiveSpan = TimeSpan.FromMinutes(10);

    private readonly PanelSession _session;
    private readonly ProjectHistory _history;
    private readonly TimeProvider _time;
    private readonly ITimer _timer;
    private Task _running = Task.CompletedTask;
    private bool _again;

    public TrendsViewModel(PanelSession session, ProjectHistory history, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(history);
        ArgumentNullException.ThrowIfNull(time);
        (_session, _history, _time) = (session, history, time);
        (From, To) = (time.GetUtcNow() - DefaultLiveSpan, time.GetUtcNow());
        Follow(session.Project);
        _timer = time.CreateTimer(_ => session.Dispatcher.Post(() => _ = RefreshIfLiveAsync()), null, RefreshPeriod, RefreshPeriod);
    }

    /// <summary>Every value the project records, for the pick list; the picked ones are drawn.</summary>
    public ObservableCollection<TrendTagViewModel> Tags { get; } = [];

    public IReadOnlyList<TrendRange> Ranges { get; } = Enum.GetValues<TrendRange>();

    /// <summary>The pane is shown (the shell follows its DockPaneViewModel.IsVisible): the live trend is redrawn only then.</summary>
    [ObservableProperty]
    public partial bool IsShown { get; set; } = true;

    /// <summary>What the App draws.</summary>
    [ObservableProperty]
    public partial TrendPlot Plot { get; private set; } = TrendPlot.Empty;

    /// <summary>Why nothing (or not everything) is drawn: no history for this project, a database that cannot be read.</summary>
    [ObservableProperty]
    public partial string? Message { get; private set; }

    /// <summary>The cursor's time in local time ("08:14:03"); empty without a cursor.</summary>
    [ObservableProperty]
    public partial string CursorTimeText { get; private set; } = string.Empty;

    public IEnumerable<TrendTagViewModel> Picked => Tags.Where(t => t.IsSelected);

    public void Dispose() => _timer.Dispose();

    /// <summary>A new or edited project: its recorded values, the first four numbers (or bits) picked, kept picks kept.</summary>
    internal void Follow(PanelProject project)
    {
        var picked = Tags.Where(t => t.IsSelected).Select(t => t.Name).ToHashSet();
        foreach (var tag in Tags)
        {
            tag.PropertyChanged -= OnTagChanged;
        }

        Tags.Clear();
        var recorded = RecordedTag.Of(project with { History = project.History with { Enabled = true } });
        foreach (var (tag, index) in recorded.Select((t, i) => (t, i)))
        {
            var station = project.Stations.First(s => s.Address == tag.Station).Name;
            Tags.Add(new TrendTagViewModel(station, tag, TrendPalette.At(index)));
        }

        var defaults = picked.Count > 0 ? Tags.Where(t => picked.Contains(t.Name)) : Tags.Where(t => t.Tag.IsNumeric).Take(4);
        foreach (var tag in defaults.DefaultIfEmpty().OfType<TrendTagViewModel>())
        {
            tag.IsSelected = true;
        }

        foreach (var tag in Tags)
        {
            tag.PropertyChanged += OnTagChanged;
        }

        _ = RefreshAsync();
    }

    /// <summary>
    /// Reads the window from the history and rebuilds <see cref="Plot"/>; live, the window first moves to now. A call while
    /// one runs makes it run once more when done (the window or the picks changed meanwhile), and waits for that.
    /// </summary>
    public Task RefreshAsync()
    {
        if (!_running.IsCompleted)
        {
            _again = true;
            return _running;
        }

        _running = RefreshUntilCurrentAsync();
        return _running;
    }

    [RelayCommand]
    private Task RefreshNowAsync() => RefreshAsync();

    private async Task RefreshUntilCurrentAsync()
    {
        do
        {
            _again = false;
            await RefreshOnceAsync();
        }
        while (_again);
    }

    private async Task RefreshOnceAsync()
    {
        try
        {
            if (IsLive)
            {
                (From, To) = (_time.GetUtcNow() - LiveSpan, _time.GetUtcNow());
            }

            var picked = Picked.ToList();
            if (_history.Current is not { } historian)
            {
                Message = "No history for this project: save it to a file and the panel records its values from then on.";
                Plot = TrendPlotBuilder.Build(picked, [.. picked.Select(t => Empty(t))], [], From, To, null, Cursor);
                return;
            }

            await historian.FlushAsync();
            var (from, to, reader) = (From, To, historian.Reader);
            var (histories, spans) = await Task.Run(() => (reader.Read([.. picked.Select(t => t.Tag)], from, to), reader.Sessions(from, to)));
            Plot = TrendPlotBuilder.Build(picked, histories, spans, from, to, IsLive ? to : null, Cursor);
            Message = picked.Count == 0 ? "Pick tags in the list to trend them." : null;
            UpdateValues(picked);
        }
        catch (HistoryException failure)
        {
            Message = failure.Message;
        }
    }

    private Task RefreshIfLiveAsync() => IsLive && IsShown ? RefreshAsync() : Task.CompletedTask;

    private void OnTagChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName == nameof(TrendTagViewModel.IsSelected))
        {
            _ = RefreshAsync();
        }
    }

    /// <summary>Each picked tag's value now (from the line, no exchange) and at the cursor (from the plot).</summary>
    private void UpdateValues(List<TrendTagViewModel> picked)
    {
        foreach (var tag in picked)
        {
            _session.Values.TryGetValue(tag.Tag.Station, tag.Tag.Address, out var now);
            tag.ValueText = now.HasValue
                ? $"{tag.Tag.Text(now.Raw.AsSpan())} ({now.Quality.ToString().ToLowerInvariant()})"
                : $"- ({now.Quality.ToString().ToLowerInvariant()})";
        }

        UpdateCursor();
    }

    private static TagHistory Empty(TrendTagViewModel tag) => new(tag.Tag.Station, tag.Tag.Address, tag.Tag.Symbol, tag.Tag.Format, []) { Scale = tag.Tag.Scale, Unit = tag.Tag.Unit };
}
