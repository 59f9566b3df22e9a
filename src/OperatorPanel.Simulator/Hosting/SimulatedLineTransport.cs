using OperatorPanel.Core.Transport;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// The PC's end of a simulated line in the line's own time, for tests and the bench: what the PC writes goes on the
/// line at the line's present time; a read runs the line forward (in steps of <see cref="Step"/>) until characters
/// have arrived whole or the read's time-out has passed on the line's clock. <see cref="Clock"/> is that clock, for
/// the code under test's time-outs. No real time passes and nothing is threaded.
/// </summary>
public sealed class SimulatedLineTransport : ITransport
{
    private readonly ISimulatedLine _line;
    private readonly Queue<(byte Value, TimeSpan ReadyAt)> _received = new();

    public SimulatedLineTransport(ISimulatedLine line, TimeSpan? step = null)
    {
        ArgumentNullException.ThrowIfNull(line);
        _line = line;
        Step = step ?? TimeSpan.FromMilliseconds(0.1);
        Clock = new LineClock(line);
    }

    public string Name => "simulated line";

    public bool IsOpen { get; private set; }

    /// <summary>How far the line runs between looks for arrived characters: the read's time resolution.</summary>
    public TimeSpan Step { get; }

    /// <summary>The line's time as a <see cref="TimeProvider"/>.</summary>
    public TimeProvider Clock { get; }

    /// <summary>When the last character the PC received ended on the line (exact on an <see cref="StlLine"/>, else to a step).</summary>
    public TimeSpan LastReceivedAt { get; private set; }

    /// <summary>How long after its stop bit a character reaches the reader (a UART's FIFO time-out, a USB adapter's latency timer).</summary>
    public TimeSpan ReceiveLatency { get; init; }

    /// <summary>How long a write takes to reach the line (a USB adapter's next USB frame).</summary>
    public TimeSpan WriteLatency { get; init; }

    /// <summary>Idle time the line must have had since the last character received before a write starts (PROFIBUS's 33-bit SYN pause).</summary>
    public TimeSpan IdleBeforeWrite { get; init; }

    public long BytesWritten { get; private set; }

    public long BytesReceived { get; private set; }

    public Task OpenAsync(CancellationToken cancellationToken)
    {
        IsOpen = true;
        return Task.CompletedTask;
    }

    public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        var at = Later(_line.Now + WriteLatency, LastReceivedAt + IdleBeforeWrite);
        if (at > _line.Now)
        {
            _line.RunUntil(at);
        }

        _line.Deliver(data.Span);
        BytesWritten += data.Length;
        return Task.CompletedTask;
    }

    public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var until = _line.Now + timeout;
        while (true)
        {
            Collect();
            if ((_received.Count > 0 && _received.Peek().ReadyAt <= _line.Now) || _line.Now >= until)
            {
                break;
            }

            // A character already arrived waits only for its latency; otherwise look again one step on.
            var next = _received.Count > 0 ? _received.Peek().ReadyAt : _line.Now + Step;
            _line.RunUntil(next < until ? next : until);
        }

        var count = 0;
        while (count < buffer.Length && _received.Count > 0 && _received.Peek().ReadyAt <= _line.Now)
        {
            buffer.Span[count++] = _received.Dequeue().Value;
        }

        BytesReceived += count;
        return Task.FromResult(count);
    }

    public void DiscardInput()
    {
        Collect();
        _received.Clear();
    }

    public ValueTask DisposeAsync()
    {
        IsOpen = false;
        return ValueTask.CompletedTask;
    }

    private void Collect()
    {
        if (_line is StlLine stl)
        {
            foreach (var character in stl.TakeCharacters())
            {
                _received.Enqueue((character.Value, character.At + ReceiveLatency));
                LastReceivedAt = character.At;
            }

            return;
        }

        foreach (var b in _line.TakeTransmitted())
        {
            _received.Enqueue((b, _line.Now + ReceiveLatency));
            LastReceivedAt = _line.Now;
        }
    }

    private static TimeSpan Later(TimeSpan a, TimeSpan b) => a > b ? a : b;

    private sealed class LineClock(ISimulatedLine line) : TimeProvider
    {
        public override long TimestampFrequency => TimeSpan.TicksPerSecond;

        public override long GetTimestamp() => line.Now.Ticks;
    }
}
