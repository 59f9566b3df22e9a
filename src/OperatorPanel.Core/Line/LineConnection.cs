using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Line;

/// <summary>
/// The transports an <see cref="ILineConnector"/> opened for a project, by port name (ignoring case, as Windows names
/// ports). The <see cref="ProjectLine"/>'s links own and dispose the transports; <paramref name="onClose"/> is for what the connector
/// runs beside them (the demo line's simulated PLCs), and runs before the transports close.
/// </summary>
public sealed class LineConnection(IReadOnlyDictionary<string, ITransport> transports, Func<ValueTask>? onClose = null) : IAsyncDisposable
{
    private readonly Dictionary<string, ITransport> _transports = new(transports, StringComparer.OrdinalIgnoreCase);
    private Func<ValueTask>? _onClose = onClose;

    /// <summary>
    /// Added to the scan allowance of every link over these transports: what the connector's own medium may add to a
    /// reply beyond the line's timing (the demo line's PLCs are simulated on a thread of this PC, which may wait for a
    /// core). Zero for real ports.
    /// </summary>
    public TimeSpan ScanAllowance { get; init; }

    /// <summary>The transport for <paramref name="portName"/>; throws when the connector gave none (its bug).</summary>
    public ITransport TransportFor(string portName) =>
        _transports.TryGetValue(portName, out var transport)
            ? transport
            : throw new InvalidOperationException($"the line connector opened no transport for port {portName}");

    public async ValueTask DisposeAsync()
    {
        if (Interlocked.Exchange(ref _onClose, null) is { } close)
        {
            await close().ConfigureAwait(false);
        }
    }
}
