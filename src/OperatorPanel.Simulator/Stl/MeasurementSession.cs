using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Sends one request at a time to a program that is the handler alone (every instruction is the handler's) and
/// records its interrupt runs (receive complete 23/24, transmit complete 9/26, timed interrupt 0 = event 10) and its
/// scans until the reply's last character has left and RCV is armed again, or, for silence, for a second and 256
/// character times (more than the longest request's work, the longest reply delay of 255 ms and the longest reply).
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
        return new MeasuredRequest(
            name, 0, 0, _scans.Count == 0 ? 0 : _scans.Max(s => s.Instructions), TimeSpan.Zero, TimeSpan.Zero,
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
        TimeSpan? listening = null;
        while (_plc.Fault is null && t < deadline && !(ended && !_port.IsTransmitting && _port.IsReceiving))
        {
            t += TimeSpan.FromMilliseconds(1);
            _plc.RunUntil(t);
            listening ??= _port.IsReceiving && _runs.Any(r => r.Event == _receiveEvent) ? t : null;
            foreach (var c in _port.TakeTransmitted())
            {
                replyChars++;
                ended |= c.Value == (byte)'>';
            }
        }

        _now = t + TimeSpan.FromMilliseconds(1);
        _plc.RunUntil(_now);
        return Measure(name, frame.Length, replyChars, listening ?? t);
    }

    private MeasuredRequest Measure(string name, int requestChars, int replyChars, TimeSpan listening)
    {
        var received = _runs.FirstOrDefault(r => r.Event == _receiveEvent)?.EndedAt ?? TimeSpan.Zero;

        // The reply delay's interval starts at its ATCH, the end of the work on the request (SMB34 = the delay in ms).
        var delay = _runs.FirstOrDefault(r => r.Event == 10);
        var done = delay is null ? listening : delay.RaisedAt - TimeSpan.FromMilliseconds(_plc.Memory.SM[34]);
        var serving = _scans.Where(s => s.Scan.EndedAt > received && s.Scan.StartedAt < done).ToList();
        var program = serving.Select(s =>
        {
            var inside = _runs.Where(r => r.StartedAt >= s.Scan.StartedAt && r.StartedAt < s.Scan.EndedAt).ToList();
            return (Instructions: s.Instructions - inside.Sum(r => r.Instructions), Time: s.Scan.Busy - Overhead - Total(inside, Time));
        }).ToList();
        return new MeasuredRequest(
            name, requestChars, replyChars, _runs.Sum(r => r.Instructions) + program.Sum(p => p.Instructions),
            Total(_runs, Time) + Total(program, p => p.Time), _runs.Count == 0 ? TimeSpan.Zero : _runs.Max(Time),
            _scans.Count == 0 ? TimeSpan.Zero : _scans.Max(s => s.Scan.Busy - Overhead), serving.Count);
    }

    private static TimeSpan Time(StlInterruptRun run) => run.EndedAt - run.StartedAt + InterruptOverhead;

    private static TimeSpan Total<T>(IEnumerable<T> items, Func<T, TimeSpan> time) => items.Aggregate(TimeSpan.Zero, (a, i) => a + time(i));
}
