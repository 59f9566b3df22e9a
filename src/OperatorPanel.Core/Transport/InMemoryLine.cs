namespace OperatorPanel.Core.Transport;

/// <summary>One direction of an <see cref="InMemoryTransportPair"/>: bytes in flight, and who closed the line.</summary>
internal sealed class InMemoryLine
{
    private readonly Lock _lock = new();
    private readonly Queue<byte> _bytes = new();
    private TaskCompletionSource? _changed;
    private string? _closedBy;

    public string? ClosedBy
    {
        get
        {
            lock (_lock)
            {
                return _closedBy;
            }
        }
    }

    public bool TryWrite(ReadOnlySpan<byte> data)
    {
        TaskCompletionSource? changed;
        lock (_lock)
        {
            if (_closedBy is not null)
            {
                return false;
            }

            foreach (var value in data)
            {
                _bytes.Enqueue(value);
            }

            (changed, _changed) = (_changed, null);
        }

        changed?.TrySetResult();
        return true;
    }

    /// <summary>Takes up to buffer.Length bytes; -1 when the line is closed.</summary>
    public int Take(Span<byte> buffer)
    {
        lock (_lock)
        {
            if (_closedBy is not null)
            {
                return -1;
            }

            var count = Math.Min(buffer.Length, _bytes.Count);
            for (var i = 0; i < count; i++)
            {
                buffer[i] = _bytes.Dequeue();
            }

            return count;
        }
    }

    /// <summary>Completes when bytes are waiting or the line closes (at once if either is already so).</summary>
    public Task WhenChangedAsync()
    {
        lock (_lock)
        {
            if (_bytes.Count > 0 || _closedBy is not null)
            {
                return Task.CompletedTask;
            }

            _changed ??= new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            return _changed.Task;
        }
    }

    public void Discard()
    {
        lock (_lock)
        {
            _bytes.Clear();
        }
    }

    public void Close(string closedBy)
    {
        TaskCompletionSource? changed;
        lock (_lock)
        {
            _closedBy ??= closedBy;
            _bytes.Clear();
            (changed, _changed) = (_changed, null);
        }

        changed?.TrySetResult();
    }
}
