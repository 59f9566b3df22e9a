using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using Serilog;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// A station that stayed silent in a cycle in which another station of the bus answered rests between tries
/// (<see cref="PollingOptions.OfflineRetryInterval"/>): every try of a silent station costs the bus its reply time-outs
/// and retries, about a second per cycle, which would slow the refresh of every station that does answer. Silence in a
/// cycle where nobody answered (the port or cable gone) never rests, so every station is good again as soon as the line
/// is back. In triggered refresh (<see cref="RefreshMode.OnDemand"/>) every refresh tries every station: someone asked.
/// </summary>
internal sealed class OfflineRest(StationTracker stations, ILogger logger)
{
    /// <summary>Replaced whole by the polling loop, so <see cref="NextTry"/> may read it from any thread.</summary>
    private ImmutableHashSet<Station> _silentWhileOthersAnswer = [];

    /// <summary>When a resting station is tried next; null when it is polled every cycle.</summary>
    public DateTimeOffset? NextTry(StationStatus status, RefreshMode mode, TimeSpan interval)
    {
        ArgumentNullException.ThrowIfNull(status);
        return mode == RefreshMode.Continuous
            && Volatile.Read(ref _silentWhileOthersAnswer).Contains(status.Station)
            && status.State is StationState.Offline or StationState.StoppedByPanel
            && status.LastFailureAt is { } failedAt
                ? failedAt + interval
                : null;
    }

    /// <summary>The station's last error when it sits this cycle out; null when it is to be polled.</summary>
    public string? IsResting(Station station, DateTimeOffset now, RefreshMode mode, TimeSpan interval)
    {
        var status = stations.Get(station);
        return NextTry(status, mode, interval) is { } next && now < next ? status.LastError ?? "offline" : null;
    }

    /// <summary>After a cycle: which of the stations it tried were silent while another station answered.</summary>
    public void NoteSilences(IEnumerable<Station> all, IReadOnlyCollection<Station> tried, TimeSpan interval)
    {
        var answering = all.Where(s => stations.Get(s).State == StationState.Online).ToHashSet();
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
                logger.Information(
                    "Station {Station} is silent while others on the bus answer: tried every {Interval} s so it does not slow their refresh",
                    station.Address, interval.TotalSeconds);
            }
        }

        Volatile.Write(ref _silentWhileOthersAnswer, silent);
    }
}
