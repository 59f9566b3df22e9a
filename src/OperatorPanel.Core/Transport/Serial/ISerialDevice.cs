namespace OperatorPanel.Core.Transport.Serial;

/// <summary>
/// An open OS serial device. Calls block (bounded by their timeout) and are made from the transport's dedicated I/O
/// threads only; failures are thrown as <see cref="PlcCommunicationException"/> of kind PortUnavailable.
/// </summary>
internal interface ISerialDevice : IDisposable
{
    /// <summary>Blocks up to <paramref name="timeout"/> for at least one byte; 0 when none came.</summary>
    int Read(Span<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken);

    /// <summary>Blocks until every byte is handed to the driver, or fails after <paramref name="timeout"/>.</summary>
    void Write(ReadOnlySpan<byte> data, TimeSpan timeout, CancellationToken cancellationToken);

    void DiscardInput();
}
