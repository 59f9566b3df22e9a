using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Simulator.Stl.Operations;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Sends one request at a time to a program that is the handler alone (every instruction is the handler's) and
/// records its interrupt runs (receive complete 23/24, transmit complete 9/26, timed interrupt 0 = event 10) and its
/// scans until the reply's last character has left and RCV is armed again, or, for silence, for a second and 256
/// character times (more than the longest request's work, the longest reply delay of 255 ms and the longest reply).
/// The handler works on the request in the scans from the receive up to the last one in which OP_PANEL executed more
/// than its idle scan does (the slice that ends the reply's check, or that receives again for silence); the reply's
/// later chunks leave from the transmit-complete routine while OP_PANEL is idle again.
/// </summary>
internal sealed class MeasurementSession
{
    private static readonly TimeSpan Settle = TimeSpan.FromMilliseconds(1000);
    private static readonly TimeSpan Overhead = TimeSpan.FromTicks(StlTiming.ScanOverhead / 100);
    private static readonly TimeSpan InterruptOverhead = TimeSpan.FromTicks(StlTiming.InterruptOverhead / 100);

    private readonly StlPlc _plc;
    private readonly FreeportPort _port;
    private readonly LineSettings _line;
    private readonly int _receiveEvent;
    private readonly List<StlInterruptRun> _runs = [];
    private readonly List<(StlScan Scan, long Instructions)> _scans = [];
    private TimeSpan _now = TimeSpan.FromMilliseconds(50);
    private long _instructionsAtScanStart;
    private long _idleInstructions;

    public MeasurementSession(StlPlc plc, FreeportPort port, LineSettings line, int portNumber)
    {
        (_plc, _port, _line) = (plc, port, line);
        _receiveEvent = portNumber == 0 ? 23 : 24;
        int[] events = portNumber == 0 ? [23, 9, 10] : [24, 26, 10];
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

    /// <summary>The handler's scans without a request: 20 ms of them.</summary>
    public MeasuredRequest Idle(string name)
    {
        _runs.Clear();
        _scans.Clear();
        _now += TimeSpan.FromMilliseconds(20);
        _plc.RunUntil(_now);
        _idleInstructions = _scans.Count == 0 ? 0 : _scans.Max(s => s.Instructions);
        return new MeasuredRequest(
            name, 0, 0, _idleInstructions, TimeSpan.Zero, TimeSpan.Zero,
            _scans.Count == 0 ? TimeSpan.Zero : _scans.Max(s => s.Scan.Busy - Overhead), 0);
    }

    public MeasuredRequest Serve(string name, byte[] frame)
    {
        _runs.Clear();
        _scans.Clear();
        _port.Deliver(frame, _now);
        var t = _now + (_line.CharacterTime * frame.Length);
        var deadline = t + Settle + (_line.CharacterTime * 256);
        var replyChars = 0;
        var ended = false;
        while (_plc.Fault is null && t < deadline && !(ended && !_port.IsTransmitting && _port.IsReceiving))
        {
            t += TimeSpan.FromMilliseconds(1);
            _plc.RunUntil(t);
            foreach (var c in _port.TakeTransmitted())
            {
                replyChars++;
                ended |= c.Value == (byte)'>';
            }
        }

        _now = t + TimeSpan.FromMilliseconds(1);
        _plc.RunUntil(_now);
        return Measure(name, frame.Length, replyChars);
    }

    private MeasuredRequest Measure(string name, int requestChars, int replyChars)
    {
        var received = _runs.FirstOrDefault(r => r.Event == _receiveEvent)?.EndedAt ?? TimeSpan.Zero;
        var program = _scans.Where(s => s.Scan.EndedAt > received).Select(s =>
        {
            var inside = _runs.Where(r => r.StartedAt >= s.Scan.StartedAt && r.StartedAt < s.Scan.EndedAt).ToList();
            return (Instructions: s.Instructions - inside.Sum(r => r.Instructions), Time: s.Scan.Busy - Overhead - Total(inside, Time));
        }).ToList();
        var serving = program.FindLastIndex(p => p.Instructions > _idleInstructions) + 1;
        var work = program.Take(serving).ToList();
        return new MeasuredRequest(
            name, requestChars, replyChars, _runs.Sum(r => r.Instructions) + work.Sum(p => p.Instructions),
            Total(_runs, Time) + Total(work, p => p.Time), _runs.Count == 0 ? TimeSpan.Zero : _runs.Max(Time),
            _scans.Count == 0 ? TimeSpan.Zero : _scans.Max(s => s.Scan.Busy - Overhead), serving);
    }

    private static TimeSpan Time(StlInterruptRun run) => run.EndedAt - run.StartedAt + InterruptOverhead;

    private static TimeSpan Total<T>(IEnumerable<T> items, Func<T, TimeSpan> time) => items.Aggregate(TimeSpan.Zero, (a, i) => a + time(i));
}
