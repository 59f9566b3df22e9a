using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Simulator.Stl.Operations;

namespace OperatorPanel.Simulator.Handlers;

/// <summary>
/// Serves one v3 request at a time to a program that is the handler alone (every instruction is the handler's), at the
/// StlTiming figures, and records its interrupt runs (receive complete 23/24, transmit complete 9/26) and its scans
/// until the reply's last byte (LEN bytes) has left and RCV is armed again, or, for silence, for half a second and
/// 256 character times. The handler works on the request in the scans from the receive up to the last one in which
/// OP_PANEL executed more than its idle scan does.
/// </summary>
public sealed class HandlerRun
{
    private static readonly TimeSpan Settle = TimeSpan.FromMilliseconds(500);
    private static readonly TimeSpan InterruptOverhead = TimeSpan.FromTicks(StlTiming.InterruptOverhead / 100);
    private static readonly TimeSpan ScanOverhead = TimeSpan.FromTicks(StlTiming.ScanOverhead / 100);

    private readonly StlPlc _plc;
    private readonly FreeportPort _port;
    private readonly LineSettings _line;
    private readonly int _receiveEvent;
    private readonly List<StlInterruptRun> _runs = [];
    private readonly List<(StlScan Scan, long Instructions)> _scans = [];
    private TimeSpan _now = TimeSpan.FromMilliseconds(50);
    private long _instructionsAtScanStart;
    private long _idleInstructions;

    public HandlerRun(StlPlc plc, FreeportPort port, LineSettings line, int portNumber)
    {
        ArgumentNullException.ThrowIfNull(plc);
        (_plc, _port, _line) = (plc, port, line);
        _receiveEvent = portNumber == 0 ? 23 : 24;
        int[] events = portNumber == 0 ? [23, 9] : [24, 26];
        _plc.InterruptServed += (_, run) =>
        {
            if (events.Contains(run.Event))
            {
                _runs.Add(run);
            }
        };
        _plc.ScanCompleted += (_, scan) =>
        {
            _scans.Add((scan, _plc.InstructionsExecuted - _instructionsAtScanStart));
            _instructionsAtScanStart = _plc.InstructionsExecuted;
        };
        _plc.RunUntil(_now);
    }

    /// <summary>The last request's scans from its receive on: the handler's instructions and time in each, interrupts included.</summary>
    public IReadOnlyList<(long Instructions, TimeSpan Time)> LastScans { get; private set; } = [];

    /// <summary>The bytes of the last reply served.</summary>
    public byte[] LastReply { get; private set; } = [];

    /// <summary>The handler's scans without a request: 20 ms of them (Instructions: the most in one scan).</summary>
    public MeasuredRequest Idle(string name)
    {
        _runs.Clear();
        _scans.Clear();
        _now += TimeSpan.FromMilliseconds(20);
        _plc.RunUntil(_now);
        _idleInstructions = _scans.Count == 0 ? 0 : _scans.Max(s => s.Instructions);
        return new MeasuredRequest(name, 0, 0, _idleInstructions, TimeSpan.Zero, TimeSpan.Zero, _scans.Count == 0 ? TimeSpan.Zero : _scans.Max(s => s.Scan.Busy - ScanOverhead), 0);
    }

    public MeasuredRequest Serve(string name, byte[] request)
    {
        ArgumentNullException.ThrowIfNull(request);
        _runs.Clear();
        _scans.Clear();
        _port.Deliver(request, _now);
        var t = _now + (_line.CharacterTime * request.Length);
        var deadline = t + Settle + (_line.CharacterTime * 256);
        var reply = new List<byte>();
        while (_plc.Fault is null && t < deadline && !(Complete(reply) && !_port.IsTransmitting && _port.IsReceiving))
        {
            t += TimeSpan.FromMilliseconds(1);
            _plc.RunUntil(t);
            reply.AddRange(_port.TakeTransmitted().Select(c => c.Value));
        }

        _now = t + TimeSpan.FromMilliseconds(1);
        _plc.RunUntil(_now);
        LastReply = [.. reply];
        return Measure(name, request.Length, reply.Count);
    }

    private static bool Complete(List<byte> reply) => reply.Count >= 2 && reply.Count >= reply[1];

    private MeasuredRequest Measure(string name, int requestBytes, int replyBytes)
    {
        var received = _runs.FirstOrDefault(r => r.Event == _receiveEvent)?.EndedAt ?? TimeSpan.Zero;
        var program = _scans.Where(s => s.Scan.EndedAt > received).Select(s =>
        {
            var inside = _runs.Where(r => r.StartedAt >= s.Scan.StartedAt && r.StartedAt < s.Scan.EndedAt).ToList();
            return (Instructions: s.Instructions - inside.Sum(r => r.Instructions), Time: s.Scan.Busy - ScanOverhead - Total(inside, Time));
        }).ToList();
        var serving = program.FindLastIndex(p => p.Instructions > _idleInstructions) + 1;
        LastScans = [.. _scans.Where(s => s.Scan.EndedAt > received).Take(serving).Select(s => (s.Instructions, s.Scan.Busy - ScanOverhead))];
        var work = program.Take(serving).ToList();
        return new MeasuredRequest(
            name, requestBytes, replyBytes, _runs.Sum(r => r.Instructions) + work.Sum(p => p.Instructions),
            Total(_runs, Time) + Total(work, p => p.Time), _runs.Count == 0 ? TimeSpan.Zero : _runs.Max(Time),
            _scans.Count == 0 ? TimeSpan.Zero : _scans.Max(s => s.Scan.Busy - ScanOverhead), serving);
    }

    private static TimeSpan Time(StlInterruptRun run) => run.EndedAt - run.StartedAt + InterruptOverhead;

    private static TimeSpan Total<T>(IEnumerable<T> items, Func<T, TimeSpan> time) => items.Aggregate(TimeSpan.Zero, (a, i) => a + time(i));
}
