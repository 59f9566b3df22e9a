using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Reconnecting: a port that failed under the link (device vanished) reports itself not open, and every later exchange
/// tries to open it again, at most once per <see cref="ReconnectOptions.ReopenInterval"/>. Meanwhile every exchange
/// fails with the port problem that started the outage, marked "reconnecting", so the status stays readable and steady.
/// </summary>
public sealed partial class PlcLink
{
    private string? _outage;
    private long? _lastFailedOpen;
    private bool _wasOpen;

    /// <summary>How the link reopens its port after a failure.</summary>
    public ReconnectOptions Reconnect { get; init; } = ReconnectOptions.Default;

    /// <summary>The port problem being worked around, e.g. "serial port COM3: ... - reconnecting"; null while connected.</summary>
    public string? Outage => Volatile.Read(ref _outage);

    private async Task EnsureOpenAsync(CancellationToken cancellationToken)
    {
        if (_transport.IsOpen)
        {
            _wasOpen = true;
            return;
        }

        if (_lastFailedOpen is { } failedAt)
        {
            var wait = Reconnect.ReopenInterval - _time.GetElapsedTime(failedAt);
            if (wait > TimeSpan.Zero)
            {
                await Task.Delay(wait, _time, cancellationToken).ConfigureAwait(false);
            }
        }

        try
        {
            await _transport.OpenAsync(cancellationToken).ConfigureAwait(false);
        }
        catch (PlcCommunicationException failure) when (failure.Kind == PlcErrorKind.PortUnavailable)
        {
            _lastFailedOpen = _time.GetTimestamp();
            if (Outage is not { } outage)
            {
                throw;
            }

            _log.Debug("{Port}: reopen failed, trying again in {Interval} ms ({Reason})", _transport.Name, Reconnect.ReopenInterval.TotalMilliseconds, failure.Message);
            throw new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, outage, failure);
        }

        _lastFailedOpen = null;
        _wasOpen = true;
        if (Interlocked.Exchange(ref _outage, null) is { } ended)
        {
            _log.Information("{Port}: reconnected after: {Outage}", _transport.Name, ended);
        }
    }

    /// <summary>
    /// A port failure on a link that had its port open starts (or continues) an outage, and its message gains
    /// "reconnecting", because the next exchange reopens the port. A port that never opened is a setup problem and keeps
    /// its own message.
    /// </summary>
    private string PortFailureMessage(PlcCommunicationException failure)
    {
        if (failure.Kind != PlcErrorKind.PortUnavailable || !_wasOpen)
        {
            return failure.Message;
        }

        if (Outage is { } outage)
        {
            return outage;
        }

        outage = $"{failure.Message} - reconnecting";
        Volatile.Write(ref _outage, outage);
        _log.Warning("{Port}: {Outage}", _transport.Name, outage);
        return outage;
    }
}
