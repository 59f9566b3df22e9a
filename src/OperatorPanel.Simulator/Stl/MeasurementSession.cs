using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Sends one request at a time and adds up the handler's interrupt runs (receive complete 23/24, transmit complete
/// 9/26, timed interrupt 0 = event 10) until the reply's last character has left and RCV is armed again, or, for
/// silence, until the longest reply delay (255 ms) has passed.
/// </summary>
internal sealed class MeasurementSession
{
    private static readonly TimeSpan Settle = TimeSpan.FromMilliseconds(300);

    private readonly StlPlc _plc;
    private readonly FreeportPort _port;
    private readonly LineSettings _line;
    private readonly int[] _events;
    private TimeSpan _now = TimeSpan.FromMilliseconds(50);
    private long _instructions;
    private TimeSpan _busy;

    public MeasurementSession(StlPlc plc, FreeportPort port, LineSettings line, int portNumber)
    {
        (_plc, _port, _line) = (plc, port, line);
        _events = portNumber == 0 ? [23, 9, 10] : [24, 26, 10];
        _plc.InterruptServed += (_, run) =>
        {
            if (_events.Contains(run.Event))
            {
                _instructions += run.Instructions;
                _busy += run.EndedAt - run.StartedAt + TimeSpan.FromTicks(StlTiming.InterruptOverhead / 100);
            }
        };
        _plc.RunUntil(_now);
    }

    public MeasuredRequest Serve(string name, byte[] frame)
    {
        (_instructions, _busy) = (0, TimeSpan.Zero);
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
        return new MeasuredRequest(name, frame.Length, replyChars, _instructions, _busy);
    }
}
