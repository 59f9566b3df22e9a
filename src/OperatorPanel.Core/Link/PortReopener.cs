using OperatorPanel.Core.Transport;
using Serilog;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Reconnecting, for a link of either protocol (<see cref="PlcLink"/>, <see cref="V3.V3Link"/>): a port that failed under
/// the link (device vanished) reports itself not open, and every later exchange tries to open it again, at most once per
/// <see cref="ReconnectOptions.ReopenInterval"/>. Meanwhile every exchange fails with the port problem that started the
/// outage, marked "reconnecting", so the status stays readable and steady.
/// </summary>
internal sealed class PortReopener(ITransport transport, TimeProvider time, ILogger log)
{
    private string? _outage;
    private long? _lastFailedOpen;
    private bool _wasOpen;

    public ReconnectOptions Options { get; set; } = ReconnectOptions.Default;

    /// <summary>The port problem being worked around, e.g. "serial port COM3: ... - reconnecting"; null while connected.</summary>
    public string? Outage => Volatile.Read(ref _outage);

    public async Task EnsureOpenAsync(CancellationToken cancellationToken)
    {
        if (transport.IsOpen)
        {
            _wasOpen = true;
            return;
        }

        if (_lastFailedOpen is { } failedAt)
        {
            var wait = Options.ReopenInterval - time.GetElapsedTime(failedAt);
            if (wait > TimeSpan.Zero)
            {
                await Task.Delay(wait, time, cancellationToken).ConfigureAwait(false);
            }
        }

        try
        {
            await transport.OpenAsync(cancellationToken).ConfigureAwait(false);
        }
        catch (PlcCommunicationException failure) when (failure.Kind == PlcErrorKind.PortUnavailable)
        {
            _lastFailedOpen = time.GetTimestamp();
            if (Outage is not { } outage)
            {
                throw;
            }

            log.Debug("{Port}: reopen failed, trying again in {Interval} ms ({Reason})", transport.Name, Options.ReopenInterval.TotalMilliseconds, failure.Message);
            throw new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, outage, failure);
        }

        _lastFailedOpen = null;
        _wasOpen = true;
        if (Interlocked.Exchange(ref _outage, null) is { } ended)
        {
            log.Information("{Port}: reconnected after: {Outage}", transport.Name, ended);
        }
    }

    /// <summary>
    /// A port failure on a link that had its port open starts (or continues) an outage, and its message gains
    /// "reconnecting", because the next exchange reopens the port. A port that never opened is a setup problem and keeps
    /// its own message.
    /// </summary>
    public string PortFailureMessage(PlcCommunicationException failure)
    {
        ArgumentNullException.ThrowIfNull(failure);
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
        log.Warning("{Port}: {Outage}", transport.Name, outage);
        return outage;
    }
}
