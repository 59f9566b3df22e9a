using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// The reference model on a line: a frame is answered when its '&gt;' arrives, and the reply leaves the station's reply
/// delay later (after any reply still queued), as the handler's timed interrupt would send it. Characters take no time.
/// </summary>
public sealed class ReferenceLine : ISimulatedLine
{
    private readonly Queue<(TimeSpan Due, byte[] Reply)> _queue = new();
    private readonly IReadOnlyList<DemoProcess> _processes;
    private TimeSpan _lastDue;

    public ReferenceLine(BusSimulator bus, IReadOnlyList<DemoProcess> processes)
    {
        ArgumentNullException.ThrowIfNull(bus);
        ArgumentNullException.ThrowIfNull(processes);
        Bus = bus;
        _processes = processes;
    }

    public BusSimulator Bus { get; }

    public TimeSpan Now { get; private set; }

    public int FramesReceived => Bus.Ports.Sum(p => p.ReceivedFrames);

    public int Replies { get; private set; }

    public TimeSpan? NextOutput => _queue.Count > 0 ? _queue.Peek().Due : null;

    public void RunUntil(TimeSpan until)
    {
        if (until <= Now)
        {
            return;
        }

        foreach (var process in _processes)
        {
            process.Advance(until - Now);
        }

        Now = until;
    }

    public void Deliver(ReadOnlySpan<byte> characters)
    {
        foreach (var station in Bus.Ports)
        {
            foreach (var reply in station.Feed(characters))
            {
                _lastDue = Max(Now + station.ReplyDelay, _lastDue);
                _queue.Enqueue((_lastDue, reply));
            }
        }
    }

    public byte[] TakeTransmitted()
    {
        var sent = new List<byte>();
        while (_queue.Count > 0 && _queue.Peek().Due <= Now)
        {
            var reply = _queue.Dequeue().Reply;
            sent.AddRange(reply);
            Replies += reply.Count(b => b == FrameCodec.EndChar);
        }

        return [.. sent];
    }

    private static TimeSpan Max(TimeSpan a, TimeSpan b) => a > b ? a : b;
}
