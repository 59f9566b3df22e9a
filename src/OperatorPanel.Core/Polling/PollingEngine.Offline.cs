using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// An offline station on a bus where another station answers rests between tries (<see cref="PollingOptions.OfflineRetryInterval"/>):
/// every try of a silent station costs the bus its reply time-outs and retries, about a second per cycle, which would
/// slow the refresh of every station that does answer. A refresh someone asked for tries every station.
/// </summary>
public sealed partial class PollingEngine
{
    private readonly HashSet<Station> _resting = [];

    /// <summary>The station's last error when it sits this cycle out; null when it is to be polled.</summary>
    private string? IsResting(Station station, DateTimeOffset now)
    {
        var status = _stations.Get(station);
        var silentAmongOthers = status.State is StationState.Offline or StationState.StoppedByPanel
            && _plan.Stations.Any(other => other != station && _stations.Get(other).State == StationState.Online);
        if (!silentAmongOthers)
        {
            _resting.Remove(station);
            return null;
        }

        if (_resting.Add(station))
        {
            _logger.Information(
                "Station {Station} is silent while others on the bus answer: tried every {Interval} s so it does not slow their refresh",
                station.Address, Options.OfflineRetryInterval.TotalSeconds);
        }

        return status.LastFailureAt is { } failedAt && now - failedAt < Options.OfflineRetryInterval ? status.LastError ?? "offline" : null;
    }

    private void MarkFramesOffline(Station station, FrameRead[] reads, string error)
    {
        for (var i = 0; i < _plan.Frames.Length; i++)
        {
            if (_plan.Frames[i].Station == station)
            {
                reads[i] = FrameRead.Failure(error, stationOffline: true);
            }
        }
    }
}
