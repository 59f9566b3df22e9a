namespace OperatorPanel.Core.Transport;

/// <summary>One end of an <see cref="InMemoryTransportPair"/>.</summary>
public sealed class InMemoryTransport : ITransport
{
    private readonly TimeProvider _timeProvider;
    private readonly InMemoryLine _incoming;
    private readonly InMemoryLine _outgoing;
    private bool _opened;

    internal InMemoryTransport(string name, TimeProvider timeProvider, InMemoryLine incoming, InMemoryLine outgoing)
    {
        Name = name;
        _timeProvider = timeProvider;
        _incoming = incoming;
        _outgoing = outgoing;
    }

    public string Name { get; }

    public bool IsOpen => _opened && _incoming.ClosedBy is null;

    public Task OpenAsync(CancellationToken cancellationToken)
    {
        cancellationToken.ThrowIfCancellationRequested();
        ThrowIfClosed();
        _opened = true;
        return Task.CompletedTask;
    }

    public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        EnsureOpen();
        cancellationToken.ThrowIfCancellationRequested();
        return _outgoing.TryWrite(data.Span) ? Task.CompletedTask : throw Unavailable(_outgoing.ClosedBy);
    }

    public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(timeout, TimeSpan.Zero);
        EnsureOpen();
        cancellationToken.ThrowIfCancellationRequested();
        var count = Take(buffer.Span);
        if (count > 0 || timeout == TimeSpan.Zero)
        {
            return Task.FromResult(count);
        }

        // The timer starts before this method returns, so a test advancing its clock right after the call sees it.
        var timedOut = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        var timer = _timeProvider.CreateTimer(
            static state => ((TaskCompletionSource)state!).TrySetResult(), timedOut, timeout, Timeout.InfiniteTimeSpan);
        return WaitForBytesAsync(buffer, timer, timedOut.Task, cancellationToken);
    }

    public void DiscardInput()
    {
        EnsureOpen();
        _incoming.Discard();
    }

    /// <summary>Closes both directions: this end and the other see PortUnavailable from now on.</summary>
    public void Close()
    {
        _incoming.Close(Name);
        _outgoing.Close(Name);
    }

    public ValueTask DisposeAsync()
    {
        Close();
        return ValueTask.CompletedTask;
    }

    private async Task<int> WaitForBytesAsync(Memory<byte> buffer, ITimer timer, Task timedOut, CancellationToken cancellationToken)
    {
        await using (timer.ConfigureAwait(false))
        {
            var canceled = Task.Delay(Timeout.InfiniteTimeSpan, cancellationToken);
            while (true)
            {
                await Task.WhenAny(_incoming.WhenChangedAsync(), timedOut, canceled).ConfigureAwait(false);
                cancellationToken.ThrowIfCancellationRequested();
                var count = Take(buffer.Span);
                if (count > 0 || timedOut.IsCompleted)
                {
                    return count;
                }
            }
        }
    }

    private int Take(Span<byte> buffer)
    {
        var count = _incoming.Take(buffer);
        return count >= 0 ? count : throw Unavailable(_incoming.ClosedBy);
    }

    private void EnsureOpen()
    {
        ThrowIfClosed();
        if (!_opened)
        {
            throw new InvalidOperationException($"{Name} is not open: call OpenAsync first");
        }
    }

    private void ThrowIfClosed()
    {
        if (_incoming.ClosedBy is { } closedBy)
        {
            throw Unavailable(closedBy);
        }
    }

    private PlcCommunicationException Unavailable(string? closedBy) =>
        new(PlcErrorKind.PortUnavailable, null, closedBy == Name ? $"{Name}: the port was closed" : $"{Name}: the other end ({closedBy}) closed the link");
}
