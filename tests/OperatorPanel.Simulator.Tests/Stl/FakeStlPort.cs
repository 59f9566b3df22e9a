using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl;

namespace OperatorPanel.Simulator.Tests.Stl;

/// <summary>
/// A port with scripted timing: a message "arrives" complete at a set time (event 23 + the bytes in the RCV buffer)
/// and a transmit completes a fixed time after XMT (event 9). Records what the program sent.
/// </summary>
internal sealed class FakeStlPort(PlcMemory memory, Func<TimeSpan> clock, int number = 0) : IStlPort
{
    private readonly Queue<(TimeSpan At, byte[] Bytes)> _incoming = new();
    private int? _receiveBuffer;
    private TimeSpan? _transmitDone;

    public int Number { get; } = number;

    public List<byte[]> Sent { get; } = [];

    public List<TimeSpan> SentAt { get; } = [];

    public int Resets { get; private set; }

    public TimeSpan TransmitTime { get; set; } = TimeSpan.FromMilliseconds(2);

    public TimeSpan? NextChange
    {
        get
        {
            TimeSpan? next = _transmitDone;
            if (_receiveBuffer is not null && _incoming.Count > 0 && (next is null || _incoming.Peek().At < next))
            {
                next = _incoming.Peek().At;
            }

            return next;
        }
    }

    public void Arrive(TimeSpan at, params byte[] bytes) => _incoming.Enqueue((at, bytes));

    public void Receive(int bufferOffset) => _receiveBuffer = bufferOffset;

    public void Transmit(int bufferOffset)
    {
        var count = memory.V[bufferOffset];
        Sent.Add(memory.V.AsSpan(bufferOffset + 1, count).ToArray());
        _transmitDone = clock() + TransmitTime;
    }

    public void AdvanceTo(TimeSpan now, ICollection<StlEvent> raised)
    {
        if (_transmitDone is { } done && done <= now)
        {
            _transmitDone = null;
            SentAt.Add(done);
            raised.Add(new StlEvent(9 + (Number * 17), done));
        }

        while (_receiveBuffer is { } buffer && _incoming.Count > 0 && _incoming.Peek().At <= now)
        {
            var (at, bytes) = _incoming.Dequeue();
            memory.V[buffer] = (byte)bytes.Length;
            bytes.CopyTo(memory.V, buffer + 1);
            _receiveBuffer = null;
            raised.Add(new StlEvent(23 + Number, at));
        }
    }

    public void Reset()
    {
        Resets++;
        _receiveBuffer = null;
        _transmitDone = null;
    }
}
