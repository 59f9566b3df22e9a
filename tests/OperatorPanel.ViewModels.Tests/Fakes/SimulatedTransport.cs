using System.Globalization;
using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol.V1;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.TestKit;
using V3Reader = OperatorPanel.Core.Protocol.V3.Reader;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>
/// A port with simulated protocol v3 PLCs behind it (<see cref="V3ReferenceLine"/>) that answer at once: the line's
/// own clock runs past the end time-out as soon as a frame arrives. Silence (a station in STOP, a wrong address) costs the
/// link's whole reply timeout on the manual clock, so nothing waits in real time. A test can pull the port
/// (<see cref="Vanished"/>), hold the next reply, or rewrite replies, and counts every frame sent.
/// </summary>
internal sealed class SimulatedTransport(string name, V3ReferenceLine line, ManualTimeProvider clock) : ITransport
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

    /// <summary>
    /// This station runs a protocol v1 handler instead of its simulated PLC: it ignores every v3 and v2 frame and answers
    /// only the v1 IDENTIFY probe, with a v1 reply (PROTOCOL_VERSION 01).
    /// </summary>
    public Station? V1Handler { get; set; }

    /// <summary>Replaces a reply frame (a whole v3 frame, cut by LEN) before the panel sees it (e.g. a read-back the PLC program changed).</summary>
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
        var replies = V1Handler is { } v1 && IsFor(data.Span, v1) ? V1Answer(data.Span, v1) : Answer(data.Span);
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

    /// <summary>The line's replies to <paramref name="frame"/>: its clock runs past every station's end time-out at once.</summary>
    private List<byte[]> Answer(ReadOnlySpan<byte> frame)
    {
        line.Deliver(frame);
        line.RunUntil(line.Now + TimeSpan.FromSeconds(1));
        var reader = new V3Reader();
        reader.Append(line.TakeTransmitted());
        var replies = new List<byte[]>();
        while (reader.TryTake(out var reply))
        {
            replies.Add(reply);
        }

        return replies;
    }

    /// <summary>A frame for <paramref name="station"/>: a v1/v2 frame names it in hex characters 1-2, a v3 frame in byte 2.</summary>
    private static bool IsFor(ReadOnlySpan<byte> frame, Station station) =>
        frame.Length > 3 && (byte.TryParse(Encoding.ASCII.GetString(frame[1..3]), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out var hex)
            ? hex == station.Address
            : frame[2] == station.Address);

    /// <summary>The v1 reply to the v1 probe (its sequence echoed), nothing for any v2 frame: a v1 handler's check rejects them.</summary>
    private static IReadOnlyList<byte[]> V1Answer(ReadOnlySpan<byte> frame, Station station)
    {
        if (!byte.TryParse(Encoding.ASCII.GetString(frame[3..5]), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out var sequence))
        {
            return []; // a v3 frame: binary, not hex characters
        }

        return frame.SequenceEqual(V1IdentifyProbe.Encode(station, sequence))
            ? [V1IdentifyProbe.Frame([(byte)station.Address, sequence, 0x81, 0x00, 0x01, 0x01, 0x03, 0x01, 0x0E, 0x77, 0x05, 0x20, 0x01, 0x00, 0x05, 0x00, 0x03, 0x00, 0x09])]
            : [];
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
