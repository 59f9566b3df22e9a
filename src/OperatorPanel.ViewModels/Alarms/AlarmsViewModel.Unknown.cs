using System.Collections.Specialized;
using System.ComponentModel;
using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// Alarms of a station not read are unknown, not clear: the banner says so ("alarms unknown: Filler offline") beside
/// the most urgent alarm, and the station's health (from the session's stations) says why.
/// </summary>
public sealed partial class AlarmsViewModel
{
    private readonly IEnumerable<StationStatusViewModel>? _stations;
    private readonly List<StationStatusViewModel> _watchedStations = [];

    /// <summary>
    /// The banner's line while any alarm flag has no good reading: "alarms unknown: Filler offline, Capper not connected";
    /// null when every flag was read. Shown whatever <see cref="MostUrgent"/> says, since the pending list may be incomplete.
    /// </summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(Summary), nameof(ShortSummary), nameof(BannerText))]
    public partial string? UnknownText { get; private set; }

    private void UpdateUnknown()
    {
        var stations = _tracker.Alarms.Where(a => !a.IsKnown).Select(a => (a.Station, a.StationName)).Distinct().ToList();
        UnknownText = stations.Count == 0
            ? null
            : "alarms unknown: " + string.Join(", ", stations.Select(s => $"{s.StationName} {Why(s.Station)}"));
    }

    /// <summary>Why a station's flags have no good reading, in the status bar's words.</summary>
    private string Why(Station station) => _watchedStations.FirstOrDefault(s => s.Address == station)?.Health switch
    {
        StationHealth.Online => "not read yet",
        StationHealth.Offline => "offline",
        StationHealth.Stopped => "not answering",
        StationHealth.StoppedByPanel => "stopped by the panel",
        StationHealth.HandlerMismatch or StationHealth.HandlerOutdated => "runs another handler",
        StationHealth.Unknown or null => "not connected",
    };

    private void WatchStations()
    {
        if (_stations is INotifyCollectionChanged collection)
        {
            collection.CollectionChanged += OnStationsReplaced;
        }

        Resubscribe();
    }

    private void UnwatchStations()
    {
        if (_stations is INotifyCollectionChanged collection)
        {
            collection.CollectionChanged -= OnStationsReplaced;
        }

        _watchedStations.ForEach(s => s.PropertyChanged -= OnStationChanged);
        _watchedStations.Clear();
    }

    private void Resubscribe()
    {
        _watchedStations.ForEach(s => s.PropertyChanged -= OnStationChanged);
        _watchedStations.Clear();
        _watchedStations.AddRange(_stations ?? []);
        _watchedStations.ForEach(s => s.PropertyChanged += OnStationChanged);
    }

    private void OnStationsReplaced(object? sender, NotifyCollectionChangedEventArgs e)
    {
        Resubscribe();
        UpdateUnknown();
    }

    private void OnStationChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName == nameof(StationStatusViewModel.Health))
        {
            UpdateUnknown();
        }
    }
}
