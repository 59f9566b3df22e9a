using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// A station that stayed silent in a cycle in which another station of the bus answered rests between tries
/// (<see cref="PollingOptions.OfflineRetryInterval"/>): every try of a silent station costs the bus its reply time-outs
/// and retries, about a second per cycle, which would slow the refresh of every station that does answer. Silence in a
/// cycle where nobody answered (the port or cable gone) never rests, so every station is good again as soon as the line
/// is back. In triggered refresh (<see cref="RefreshMode.OnDemand"/>) every refresh tries every station: someone asked.
/// </summary>
public sealed partial class PollingEngine
{
    /// <summary>Replaced whole by the polling loop, so <see cref="GetStationStatus"/> may read it from any thread.</summary>
    private ImmutableHashSet<Station> _silentWhileOthersAnswer = [];

    /// <summary>The station's last error when it sits this cycle out; null when it is to be polled.</summary>
    private string? IsResting(Station station, DateTimeOffset now)
    {
        var status = _stations.Get(station);
        return NextTry(station, status) is { } next && now < next ? status.LastError ?? "offline" : null;
    }

    /// <summary>When a resting station is tried next; null when it is polled every cycle.</summary>
    private DateTimeOffset? NextTry(Station station, StationStatus status) =>
        Mode == RefreshMode.Continuous
        && Volatile.Read(ref _silentWhileOthersAnswer).Contains(station)
        && status.State is StationState.Offline or StationState.StoppedByPanel
        && status.LastFailureAt is { } failedAt
            ? failedAt + Options.OfflineRetryInterval
            : null;

    /// <summary>After a cycle: which of the stations it tried were silent while another station answered.</summary>
    private void NoteSilences(IReadOnlyCollection<Station> tried)
    {
        var answering = _plan.Stations.Where(s => _stations.Get(s).State == StationState.Online).ToHashSet();
        if (!tried.Any(answering.Contains))
        {
            // Nobody answered in this cycle: the port or cable is gone, so a station resting since another answered earlier
            // (the port vanished mid-cycle) is tried every cycle again, and shows as soon as the line is back.
            Volatile.Write(ref _silentWhileOthersAnswer, []);
            return;
        }

        var silent = _silentWhileOthersAnswer.Except(answering);
        foreach (var station in tried.Where(s => !answering.Contains(s)))
        {
            if (!silent.Contains(station))
            {
                silent = silent.Add(station);
                _logger.Information(
                    "Station {Station} is silent while others on the bus answer: tried every {Interval} s so it does not slow their refresh",
                    station.Address, Options.OfflineRetryInterval.TotalSeconds);
            }
        }

        Volatile.Write(ref _silentWhileOthersAnswer, silent);
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
