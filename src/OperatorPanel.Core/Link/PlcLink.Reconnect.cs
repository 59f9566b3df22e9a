namespace OperatorPanel.Core.Link;

/// <summary>
/// Reconnecting (<see cref="PortReopener"/>, shared with the v3 link): a port that failed under the link (device
/// vanished) reports itself not open, and every later exchange tries to open it again, at most once per
/// <see cref="ReconnectOptions.ReopenInterval"/>. Meanwhile every exchange fails with the port problem that started the
/// outage, marked "reconnecting", so the status stays readable and steady.
/// </summary>
public sealed partial class PlcLink
{
    private readonly PortReopener _port;

    /// <summary>How the link reopens its port after a failure.</summary>
    public ReconnectOptions Reconnect
    {
        get => _port.Options;
        init => _port.Options = value;
    }

    /// <summary>The port problem being worked around, e.g. "serial port COM3: ... - reconnecting"; null while connected.</summary>
    public string? Outage => _port.Outage;

    private Task EnsureOpenAsync(CancellationToken cancellationToken) => _port.EnsureOpenAsync(cancellationToken);

    private string PortFailureMessage(Transport.PlcCommunicationException failure) => _port.PortFailureMessage(failure);
}
