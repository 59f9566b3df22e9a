namespace OperatorPanel.Core.Transport;

/// <summary>
/// Keeps one read request outstanding on a stream, never cancelled, and hands its bytes out under timeouts of its own.
/// Used for the serial port on Linux/macOS, where the library's timed read is an async request cancelled at the
/// timeout: bytes its I/O loop reads at that moment are dropped with the cancelled request, and a timeout below 30 ms
/// is raised to 30 ms. A request that is never cancelled loses nothing and still fails when the device hangs up.
/// Reads come from one thread (the transport's read lane); <see cref="Discard"/> may come from another.
/// </summary>
internal sealed class OutstandingStreamRead(Stream stream)
{
    private readonly Lock _lock = new();
    private readonly byte[] _received = new byte[4096];
    private int _offset;
    private int _count;
    private Task<int>? _pending;

    /// <summary>Up to <paramref name="timeout"/> for at least one byte; 0 when none came. Stream errors are rethrown.</summary>
    public int Read(Span<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var deadline = Environment.TickCount64 + (long)Math.Ceiling(timeout.TotalMilliseconds);
        while (true)
        {
            Task<int> pending;
            lock (_lock)
            {
                if (_count > 0)
                {
                    var taken = Math.Min(_count, buffer.Length);
                    _received.AsSpan(_offset, taken).CopyTo(buffer);
                    _offset += taken;
                    _count -= taken;
                    return taken;
                }

                pending = _pending ??= stream.ReadAsync(_received, 0, _received.Length, CancellationToken.None);
            }

            if (!WaitFor(pending, deadline, cancellationToken))
            {
                return 0;
            }

            lock (_lock)
            {
                if (_pending != pending)
                {
                    continue;
                }

                _pending = null;
                (_offset, _count) = (0, pending.GetAwaiter().GetResult());

                // A serial stream never ends while its device is there: end of stream is a hang-up, and reading on would spin.
                if (_count == 0)
                {
                    throw new IOException("end of stream: the device hung up");
                }
            }
        }
    }

    /// <summary>
    /// Task.Wait, not WaitAny: its wake-up runs inline when the request completes, where WaitAny's would queue to the
    /// thread pool (the library completes requests with asynchronous continuations). A failed request counts as done;
    /// its exception is rethrown when the result is taken.
    /// </summary>
    private static bool WaitFor(Task<int> pending, long deadline, CancellationToken cancellationToken)
    {
        var remaining = (int)Math.Clamp(deadline - Environment.TickCount64, 0, int.MaxValue);
        try
        {
            return pending.Wait(remaining, cancellationToken);
        }
        catch (AggregateException)
        {
            return true;
        }
    }

    /// <summary>Drops bytes already taken from the device but not handed out (the caller flushes the device's own).</summary>
    public void Discard()
    {
        lock (_lock)
        {
            _count = 0;
            if (_pending is { IsCompletedSuccessfully: true })
            {
                _pending = null;
            }
        }
    }

    /// <summary>After the stream is closed the outstanding request fails; its exception is expected, so it is observed.</summary>
    public void Forget() => _ = _pending?.Exception;
}
