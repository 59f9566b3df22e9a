namespace OperatorPanel.Core.Transport;

/// <summary>
/// A byte pipe to an RS-485 bus: a serial port, a radio module, or an in-memory pair in tests. Bytes only; framing is the
/// protocol's business. Failures surface as <see cref="PlcCommunicationException"/> (kind <see cref="PlcErrorKind.PortUnavailable"/>).
/// </summary>
public interface ITransport : IAsyncDisposable
{
    /// <summary>What a technician would call it: "COM3", "/dev/ttyUSB0".</summary>
    string Name { get; }

    bool IsOpen { get; }

    Task OpenAsync(CancellationToken cancellationToken);

    Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken);

    /// <summary>
    /// Waits up to <paramref name="timeout"/> for at least one byte and returns how many were read; 0 means the timeout passed
    /// with nothing received.
    /// </summary>
    Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken);

    /// <summary>Drops bytes received but not yet read (stale replies, line noise) before a new request.</summary>
    void DiscardInput();
}
