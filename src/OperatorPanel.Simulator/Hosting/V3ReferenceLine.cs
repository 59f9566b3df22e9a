using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Reference.V3;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// Protocol v3 reference stations (Reference/V3/ReferenceHandler) on one simulated RS-485 line, for the panel's v3
/// side: every byte reaches every station's RCV, which starts on '&lt;' and ends the message when the station's end
/// time-out (SMW92, END_TIMEOUT_MS) passes without a character or its request buffer is full; the message is handed to
/// the model then, and its reply leaves at that moment (after any reply still going out) and also reaches the other
/// stations' RCV, as on a real bus. A station that answers is deaf until its reply's last byte has left (docs/protocol.md
/// section 4: its RCV is armed again only then), as the generated handler is. Characters take <see cref="CharacterTime"/> each (zero: no time). <see cref="Tamper"/>
/// lets a test drop or change a reply on its way to the PC (a lost or corrupted reply). With demo processes
/// (<c>opanel simulate</c>, the demo line) the bottle filler drives each station's memory as time passes.
/// </summary>
public sealed class V3ReferenceLine : ISimulatedLine
{
    private readonly List<Receiver> _receivers;
    private readonly List<DemoProcess> _processes;
    private readonly Queue<(TimeSpan Due, byte[] Reply)> _out = new();
    private TimeSpan _lastDue;

    public V3ReferenceLine(IEnumerable<ReferenceHandler> stations, bool runProcess = false)
    {
        ArgumentNullException.ThrowIfNull(stations);
        _receivers = [.. stations.Select(s => new Receiver(new V3DemoStation(s)))];
        _processes = runProcess ? [.. _receivers.Select(r => new DemoProcess(r.Demo))] : [];
    }

    public IReadOnlyList<ReferenceHandler> Stations => [.. _receivers.Select(r => r.Station)];

    /// <summary>Whether the demo bottle filler drives the stations' memory.</summary>
    public bool RunsProcess => _processes.Count > 0;

    public TimeSpan Now { get; private set; }

    /// <summary>How long one character takes on the wire (10 bits at the baud rate); zero by default.</summary>
    public TimeSpan CharacterTime { get; init; }

    public int FramesReceived { get; private set; }

    public int Replies { get; private set; }

    /// <summary>Requests whose reply <see cref="Tamper"/> dropped.</summary>
    public int DroppedReplies { get; private set; }

    /// <summary>
    /// Called with each reply as the station sends it, and the request it answers: returns the bytes the PC gets, or null
    /// to lose the reply (the station did act). Null: every reply arrives as sent.
    /// </summary>
    public Func<byte[], byte[], byte[]?>? Tamper { get; set; }

    public TimeSpan? NextOutput =>
        _out.Count > 0 ? _out.Peek().Due : _receivers.Where(r => r.Pending).Select(r => (TimeSpan?)r.EndsAt).Min();

    public void RunUntil(TimeSpan until)
    {
        while (_receivers.Where(r => r.Pending && r.EndsAt <= until).OrderBy(r => r.EndsAt).FirstOrDefault() is { } ended)
        {
            Advance(ended.EndsAt);
            Complete(ended);
        }

        Advance(until);
    }

    private void Advance(TimeSpan to)
    {
        if (to <= Now)
        {
            return;
        }

        foreach (var process in _processes)
        {
            process.Advance(to - Now);
        }

        Now = to;
    }

    public void Deliver(ReadOnlySpan<byte> characters)
    {
        var at = Now;
        foreach (var b in characters)
        {
            at += CharacterTime;
            foreach (var receiver in _receivers)
            {
                receiver.Take(b, at);
            }
        }

        foreach (var full in _receivers.Where(r => r.Full).ToList())
        {
            Complete(full);
        }
    }

    public byte[] TakeTransmitted()
    {
        var sent = new List<byte>();
        while (_out.Count > 0 && _out.Peek().Due <= Now)
        {
            sent.AddRange(_out.Dequeue().Reply);
        }

        return [.. sent];
    }

    private void Complete(Receiver receiver)
    {
        var message = receiver.End();
        FramesReceived++;
        if (receiver.Demo.HandleMessage(message) is not { } reply)
        {
            return;
        }

        Replies++;
        var due = Max(receiver.EndsAt, _lastDue);
        _lastDue = due + (CharacterTime * reply.Length);
        receiver.DeafUntil = _lastDue;
        foreach (var other in _receivers.Where(r => r != receiver))
        {
            foreach (var b in reply)
            {
                other.Take(b, due);
            }
        }

        var arriving = Tamper is { } tamper ? tamper(message, reply) : reply;
        if (arriving is null)
        {
            DroppedReplies++;
            return;
        }

        _out.Enqueue((_lastDue, arriving));
    }

    private static TimeSpan Max(TimeSpan a, TimeSpan b) => a > b ? a : b;

    /// <summary>One station's RCV: idle until '&lt;', then every character until the end time-out or a full buffer.</summary>
    private sealed class Receiver(V3DemoStation station)
    {
        private readonly List<byte> _message = [];
        private TimeSpan _lastAt;

        public V3DemoStation Demo { get; } = station;

        public ReferenceHandler Station => Demo.Handler;

        public bool Pending => _message.Count > 0;

        public bool Full => _message.Count >= Station.Setup.Shape.RequestBytes;

        public TimeSpan EndsAt => _lastAt + TimeSpan.FromMilliseconds(Station.Setup.EndTimeoutMs);

        /// <summary>Until its reply's last byte has left, the station's RCV is not armed: what arrives meanwhile is lost.</summary>
        public TimeSpan DeafUntil { get; set; }

        public void Take(byte b, TimeSpan at)
        {
            if (at < DeafUntil || (_message.Count == 0 && b != Limits.Start))
            {
                return;
            }

            _message.Add(b);
            _lastAt = at;
        }

        public byte[] End()
        {
            byte[] message = [.. _message];
            _message.Clear();
            return message;
        }
    }
}
