using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Transport;
using Serilog;

namespace OperatorPanel.Core.Polling;

/// <summary>
/// Per-station link state. Every failure is logged: at Warning when the station goes offline, or when the error text
/// changes while it is not offline; at Debug while it stays offline (an unplugged PLC must not flood the log, whatever
/// request each cycle happens to lose).
/// </summary>
internal sealed class StationTracker(TimeProvider time, ILogger logger)
{
    private readonly Lock _lock = new();
    private readonly Dictionary<Station, StationStatus> _statuses = [];

    public StationStatus Get(Station station)
    {
        lock (_lock)
        {
            return _statuses.GetValueOrDefault(station) ?? StationStatus.Initial(station);
        }
    }

    /// <summary>A valid reply came; <paramref name="refusal"/> is set when it was an error reply.</summary>
    public void RecordReply(Station station, string? refusal = null)
    {
        var before = Get(station);
        var after = before with
        {
            State = StationState.Online,
            LastError = refusal ?? before.LastError,
            LastErrorKind = refusal is null ? before.LastErrorKind : null,
            ConsecutiveFailures = 0,
            LastReplyAt = time.GetUtcNow(),
        };
        Store(after);
        if (before.State == StationState.Offline)
        {
            logger.Information("{Station} is back online", station.Address);
        }
        else if (before.State == StationState.StoppedByPanel)
        {
            logger.Information("Station {Station} answers again after the panel stopped it: someone set RUN", station.Address);
        }

        if (refusal is not null && refusal != before.LastError)
        {
            logger.Warning("{Station} refused a request: {Error}", station.Address, refusal);
        }
    }

    /// <summary>
    /// Records a failed exchange and returns its message and whether the station is now offline, in which case the
    /// cycle skips the station's remaining frames so it costs at most one timeout per cycle.
    /// </summary>
    public (string Message, bool Offline) RecordFailure(Station station, Exception exception)
    {
        var (message, offline) = exception switch
        {
            PlcCommunicationException { Kind: PlcErrorKind.NoAnswer or PlcErrorKind.Timeout or PlcErrorKind.PortUnavailable or PlcErrorKind.AnotherMaster } e =>
                ($"{e.Kind}: {e.Message}", true),
            PlcCommunicationException e => ($"{e.Kind}: {e.Message}", false),
            _ => ($"link error ({exception.GetType().Name}): {exception.Message}", true),
        };
        var before = Get(station);
        // A station the panel stopped is expected to be silent; a lost port is still news.
        var stopped = before.State == StationState.StoppedByPanel && exception is PlcCommunicationException { Kind: PlcErrorKind.NoAnswer or PlcErrorKind.Timeout };
        var after = before with
        {
            State = offline && !stopped ? StationState.Offline : before.State,
            LastError = stopped ? before.LastError : message,
            LastErrorKind = stopped ? before.LastErrorKind : (exception as PlcCommunicationException)?.Kind,
            ConsecutiveFailures = before.ConsecutiveFailures + 1,
            LastFailureAt = time.GetUtcNow(),
        };
        Store(after);
        if (exception is not PlcCommunicationException)
        {
            logger.Error(exception, "{Station}: unexpected link exception, polling continues", station.Address);
        }
        else if (!stopped && (after.State != before.State || (after.State != StationState.Offline && message != before.LastError)))
        {
            logger.Warning("{Station}: {Error} ({State})", station.Address, message, after.State);
        }
        else
        {
            logger.Debug("{Station}: {Error} again ({Failures} in a row)", station.Address, message, after.ConsecutiveFailures);
        }

        return (message, offline);
    }

    /// <summary>The station acknowledged a STOP from the panel and a following IDENTIFY found it silent.</summary>
    public void RecordStoppedByPanel(Station station)
    {
        Store(Get(station) with { State = StationState.StoppedByPanel, LastError = "stopped by the panel" });
        logger.Information("Station {Station} stopped by the panel: tried until it answers again, less often while others on the bus answer", station.Address);
    }

    /// <summary>A reply came but did not fit the request; the station is answering, so it stays as it was.</summary>
    public void RecordBadReply(Station station, string message)
    {
        var before = Get(station);
        Store(before with { LastError = message, LastErrorKind = null, ConsecutiveFailures = before.ConsecutiveFailures + 1 });
        logger.Warning("{Station}: {Error}", station.Address, message);
    }

    private void Store(StationStatus status)
    {
        lock (_lock)
        {
            _statuses[status.Station] = status;
        }
    }
}
