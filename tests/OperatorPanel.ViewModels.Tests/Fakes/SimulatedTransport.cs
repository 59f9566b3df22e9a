using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.TestKit;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>
/// A port with simulated PLCs behind it that answer at once. Silence (a station in STOP, a wrong address) costs the
/// link's whole reply timeout on the manual clock, so nothing waits in real time. A test can pull the port
/// (<see cref="Vanished"/>), hold the next reply, or rewrite replies, and counts every frame sent.
/// </summary>
internal sealed class SimulatedTransport(string name, BusSimulator bus, ManualTimeProvider clock) : ITransport
{
    private readonly Lock _lock = new();
    private readonly Queue<byte> _received = new();
    private readonly List<byte[]> _sent = [];
    private TaskCompletionSource? _gate;
    private TaskCompletionSource _held = new(TaskCreationOptions.RunContinuationsAsynchronously);

    public string Name { get; } = name;

    public bool IsOpen { get; private set; }

    /// <summary>The port is gone (USB adapter pulled): open, write and read throw PortUnavailable.</summary>
    public bool Vanished { get; set; }

    /// <summary>Replaces a reply frame before the panel sees it (e.g. a read-back the PLC program changed).</summary>
    public Func<byte[], byte[]>? RewriteReply { get; set; }

    public int FramesSent
    {
        get { lock (_lock) { return _sent.Count; } }
    }

    /// <summary>The next reply waits until <see cref="Release"/>; the task completes once it is waiting.</summary>
    public Task HoldNextReply()
    {
        lock (_lock)
        {
            _gate = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            _held = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            return _held.Task;
        }
    }

    public void Release()
    {
        lock (_lock)
        {
            _gate?.TrySetResult();
            _gate = null;
        }
    }

    public Task OpenAsync(CancellationToken cancellationToken)
    {
        ThrowIfVanished();
        IsOpen = true;
        return Task.CompletedTask;
    }

    public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        ThrowIfVanished();
        var replies = bus.Feed(data.Span);
        lock (_lock)
        {
            _sent.Add(data.ToArray());
            foreach (var reply in replies)
            {
                foreach (var b in RewriteReply?.Invoke(reply) ?? reply)
                {
                    _received.Enqueue(b);
                }
            }
        }

        return Task.CompletedTask;
    }

    public async Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        ThrowIfVanished();
        Task? gate;
        lock (_lock)
        {
            gate = _received.Count > 0 ? _gate?.Task : null;
            if (gate is not null)
            {
                _held.TrySetResult();
            }
        }

        if (gate is not null)
        {
            await gate.WaitAsync(cancellationToken);
        }

        lock (_lock)
        {
            var count = 0;
            while (count < buffer.Length && _received.TryDequeue(out var b))
            {
                buffer.Span[count++] = b;
            }

            if (count > 0)
            {
                return count;
            }
        }

        clock.Advance(timeout);
        return 0;
    }

    public void DiscardInput()
    {
        lock (_lock)
        {
            _received.Clear();
        }
    }

    public ValueTask DisposeAsync()
    {
        IsOpen = false;
        return ValueTask.CompletedTask;
    }

    private void ThrowIfVanished()
    {
        if (Vanished)
        {
            IsOpen = false;
            throw new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, $"{Name}: the port has gone (device removed)");
        }
    }
}
