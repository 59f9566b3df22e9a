using OperatorPanel.Core.Transport;

namespace OperatorPanel.IntegrationTests.Polling;

/// <summary>
/// The PLC end of the pty, wrapped so a test can act on the simulated PLC's own thread: <see cref="OnReceived"/> runs
/// after every chunk of received characters and before the host handles them (a PLC program scan between two
/// receive interrupts), and <see cref="NoiseBeforeReply"/> puts garbage on the line ahead of a reply (a noisy bus).
/// </summary>
internal sealed class PlcPortTap(ITransport inner) : ITransport
{
    private readonly Lock _lock = new();
    private readonly System.Text.StringBuilder _received = new();
    private readonly System.Text.StringBuilder _sent = new();
    private int _writes;

    public Action? OnReceived { get; set; }

    /// <summary>Given the number of the reply about to be sent (from 0), the garbage to send ahead of it, or empty.</summary>
    public Func<int, byte[]>? NoiseBeforeReply { get; set; }

    /// <summary>Replies written so far, counted before the first character leaves, so a reply the PC has is counted.</summary>
    public int Replies => Volatile.Read(ref _writes);

    /// <summary>Every character the PLC end has received so far, as ASCII.</summary>
    public string Received
    {
        get { lock (_lock) { return _received.ToString(); } }
    }

    /// <summary>Every character the PLC end has sent so far (replies and any noise), as ASCII.</summary>
    public string Sent
    {
        get { lock (_lock) { return _sent.ToString(); } }
    }

    public string Name => inner.Name;

    public bool IsOpen => inner.IsOpen;

    public Task OpenAsync(CancellationToken cancellationToken) => inner.OpenAsync(cancellationToken);

    public async Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        var number = Interlocked.Increment(ref _writes) - 1;
        var noise = NoiseBeforeReply?.Invoke(number) ?? [];
        lock (_lock) { _sent.Append(System.Text.Encoding.ASCII.GetString(noise)).Append(System.Text.Encoding.ASCII.GetString(data.Span)); }
        if (noise.Length > 0)
        {
            await inner.WriteAsync(noise, cancellationToken);
        }

        await inner.WriteAsync(data, cancellationToken);
    }

    public async Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var count = await inner.ReadAsync(buffer, timeout, cancellationToken);
        if (count > 0)
        {
            lock (_lock) { _received.Append(System.Text.Encoding.ASCII.GetString(buffer.Span[..count])); }
            OnReceived?.Invoke();
        }

        return count;
    }

    public void DiscardInput() => inner.DiscardInput();

    public ValueTask DisposeAsync() => inner.DisposeAsync();
}
