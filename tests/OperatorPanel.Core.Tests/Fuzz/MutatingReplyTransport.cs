using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Tests.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Fuzz;

/// <summary>
/// A bus whose station answers each request frame with a true reply or a mutated one (<see cref="ReplyMutator"/>),
/// sometimes after our own echo or a late reply to an older SEQ, handed out in random pieces. Silence advances the
/// manual clock by the whole read timeout, so no real time passes. Every reply it put on the wire is kept for the test.
/// Now and then the USB adapter vanishes in a write or a read, as SerialPortTransport reports it; the next open succeeds.
/// </summary>
internal sealed class MutatingReplyTransport(Random random, ManualTimeProvider clock) : ITransport
{
    private readonly Queue<byte> _pending = new();

    public string Name => "fuzz-bus";

    public bool IsOpen { get; private set; }

    /// <summary>The request the test is exchanging; the link stamps its own SEQ, which the reply echoes.</summary>
    public PlcRequest? Current { get; set; }

    /// <summary>Request frames written since the test last cleared the list.</summary>
    public int Writes { get; set; }

    /// <summary>Replies put on the wire since the test last cleared the list.</summary>
    public List<ReplyMutation> Replies { get; } = [];

    public Task OpenAsync(CancellationToken cancellationToken)
    {
        IsOpen = true;
        return Task.CompletedTask;
    }

    public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        Writes++;
        MaybeVanish("write");
        if (Current is null || !FrameCodec.TryDecode(data.Span, out var frame, out _))
        {
            return Task.CompletedTask; // a v1 probe: this bus has no v1 handler, so it stays silent
        }

        var request = Current with { Sequence = frame.Sequence };
        var reply = ResponseCodec.Encode(RandomMessages.ResponseTo(random, request));
        var mutation = random.Next(5) < 2 ? new ReplyMutation(reply, "untouched", MayBeAccepted: true) : ReplyMutator.Mutate(reply, request, random);
        switch (random.Next(6))
        {
            case 0:
                Enqueue(data.Span); // the RS-485 adapter's echo of our request
                break;
            case 1:
                Enqueue(ResponseCodec.Encode(RandomMessages.ResponseTo(random, Current with { Sequence = (byte)(frame.Sequence - 1) })));
                break;
        }

        Replies.Add(mutation);
        Enqueue(mutation.Chars);
        return Task.CompletedTask;
    }

    public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        MaybeVanish("read");
        if (_pending.Count == 0)
        {
            clock.Advance(timeout);
            return Task.FromResult(0);
        }

        var count = Math.Min(buffer.Length, random.Next(1, 40));
        var taken = 0;
        while (taken < count && _pending.TryDequeue(out var b))
        {
            buffer.Span[taken++] = b;
        }

        return Task.FromResult(taken);
    }

    public void DiscardInput() => _pending.Clear();

    public ValueTask DisposeAsync() => ValueTask.CompletedTask;

    private void MaybeVanish(string action)
    {
        if (random.Next(60) == 0)
        {
            IsOpen = false;
            throw new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, $"serial port {Name}: {action} failed: Input/output error (EIO) - the device vanished (unplugged?)");
        }
    }

    private void Enqueue(ReadOnlySpan<byte> chars)
    {
        foreach (var b in chars)
        {
            _pending.Enqueue(b);
        }
    }
}
