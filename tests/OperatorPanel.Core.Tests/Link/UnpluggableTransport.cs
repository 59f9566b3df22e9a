using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Link;

/// <summary>
/// A USB-serial adapter that can be pulled and plugged back, behaving as SerialPortTransport does: once the device is
/// gone the next call fails with "the device vanished" and the transport reports itself not open; opening fails while
/// the device is away. While present, every READ of MB0 is answered with <see cref="Mb0"/> under the request's sequence.
/// </summary>
internal sealed class UnpluggableTransport : ITransport
{
    private readonly Queue<byte> _reply = new();
    private bool _present = true;
    private bool _open;
    private bool _failed;

    public string Name => "/dev/ttyUSB0";

    public bool IsOpen => _open && !_failed;

    public int OpenAttempts { get; private set; }

    public byte Mb0 { get; set; }

    public void Unplug() => _present = false;

    public void PlugIn() => _present = true;

    public Task OpenAsync(CancellationToken cancellationToken)
    {
        OpenAttempts++;
        if (!_present)
        {
            throw new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, $"serial port {Name}: open failed: No such file or directory (ENOENT) - no such port");
        }

        (_open, _failed) = (true, false);
        return Task.CompletedTask;
    }

    public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        EnsurePresent("write");
        FrameCodec.TryDecode(data.Span, out var request, out _).Should().BeTrue("the link sends well-formed frames");
        foreach (var b in ResponseCodec.Encode(new ReadResponse(new(request.Station), request.Sequence, [Mb0]) { RequestCheck = FrameCodec.CheckOf(request) }))
        {
            _reply.Enqueue(b);
        }

        return Task.CompletedTask;
    }

    public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        EnsurePresent("read");
        var count = 0;
        while (count < buffer.Length && _reply.TryDequeue(out var b))
        {
            buffer.Span[count++] = b;
        }

        return Task.FromResult(count);
    }

    public void DiscardInput()
    {
        EnsurePresent("discard input");
        _reply.Clear();
    }

    public ValueTask DisposeAsync() => ValueTask.CompletedTask;

    private void EnsurePresent(string action)
    {
        _open.Should().BeTrue($"the link must open the port before it may {action}");
        if (!_present || _failed)
        {
            _failed = true;
            throw new PlcCommunicationException(
                PlcErrorKind.PortUnavailable, null, $"serial port {Name}: {action} failed: Input/output error (EIO) - the device vanished (unplugged?)");
        }
    }
}
