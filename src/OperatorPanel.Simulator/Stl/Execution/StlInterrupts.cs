using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// Interrupt events: which routine each event is attached to, a queue per priority group (communications, I/O,
/// timed), first come first served within a group (docs/sources/s7200-facts.md section 5). Queue depths 4/16/8,
/// communications 8 on CPU 224XP/226; a full queue sets SM4.0/SM4.1/SM4.2 and the event is lost. SM4.4 shows whether
/// interrupts are enabled. The timed interrupts 0 and 1 (events 10 and 11) are raised here from SMB34/SMB35.
/// </summary>
internal sealed class StlInterrupts
{
    private readonly List<StlQueuedEvent>[] _queues = [[], [], []];
    private readonly int[] _attached = new int[34];
    private readonly long[] _timedInterval = new long[2];
    private readonly long[] _timedNext = new long[2];
    private readonly int[] _capacity;
    private readonly byte[] _sm;
    private int _queued;

    public StlInterrupts(CpuProfile cpu, byte[] sm)
    {
        _capacity = [cpu.CommunicationPorts > 1 ? 8 : 4, 16, 8];
        _sm = sm;
        Reset();
    }

    /// <summary>ENI / DISI; cleared when the CPU leaves RUN.</summary>
    public bool Enabled { get; private set; }

    public bool HasQueued => _queued > 0;

    /// <summary>When a timed interrupt next falls due (ns); long.MaxValue when none is attached.</summary>
    public long NextTimed => Math.Min(_timedNext[0], _timedNext[1]);

    /// <summary>Back to power-up: nothing attached, nothing queued, interrupts disabled.</summary>
    public void Reset()
    {
        Array.Fill(_attached, -1);
        Array.Fill(_timedNext, long.MaxValue);
        foreach (var queue in _queues)
        {
            queue.Clear();
        }

        _queued = 0;
        Enable(false);
    }

    public void Enable(bool enabled)
    {
        Enabled = enabled;
        _sm[4] = (byte)(enabled ? _sm[4] | 0x10 : _sm[4] & ~0x10);
    }

    /// <summary>ATCH; for the timed events 10/11 the interval in SMB34/SMB35 (1-255 ms) is captured now.</summary>
    public void Attach(int block, int number, long now)
    {
        _attached[number] = block;
        if (number is 10 or 11)
        {
            var interval = _sm[34 + number - 10] * StlTime.Millisecond;
            _timedInterval[number - 10] = interval;
            _timedNext[number - 10] = interval > 0 ? now + interval : long.MaxValue;
        }
    }

    public void Detach(int number)
    {
        _attached[number] = -1;
        if (number is 10 or 11)
        {
            _timedNext[number - 10] = long.MaxValue;
        }
    }

    /// <summary>An event occurred at <paramref name="at"/>: queued when a routine is attached to it, else ignored.</summary>
    public void Enqueue(int number, long at)
    {
        var block = _attached[number];
        if (block < 0)
        {
            return;
        }

        var group = GroupOf(number);
        var queue = _queues[group];
        if (queue.Count >= _capacity[group])
        {
            _sm[4] |= (byte)(1 << group);
            return;
        }

        var index = queue.Count;
        while (index > 0 && queue[index - 1].At > at)
        {
            index--;
        }

        queue.Insert(index, new StlQueuedEvent(number, block, at));
        _queued++;
    }

    /// <summary>The next event to serve: the oldest of the highest group that has one.</summary>
    public StlQueuedEvent TakeNext()
    {
        var queue = _queues.First(q => q.Count > 0);
        var next = queue[0];
        queue.RemoveAt(0);
        _queued--;
        return next;
    }

    /// <summary>SM4.0-SM4.2 are reset when their queue is emptied (seed 002, Table C-5).</summary>
    public void ClearOverflowOfEmptyQueues()
    {
        for (var group = 0; group < _queues.Length; group++)
        {
            if (_queues[group].Count == 0)
            {
                _sm[4] &= (byte)~(1 << group);
            }
        }
    }

    /// <summary>Queues every timed interrupt that fell due up to <paramref name="now"/>.</summary>
    public void RaiseTimed(long now)
    {
        for (var timer = 0; timer < 2; timer++)
        {
            while (_timedNext[timer] <= now)
            {
                Enqueue(10 + timer, _timedNext[timer]);
                _timedNext[timer] += _timedInterval[timer];
            }
        }
    }

    private static int GroupOf(int number) => number switch
    {
        8 or 9 or 23 or 24 or 25 or 26 => 0,
        10 or 11 or 21 or 22 => 2,
        _ => 1,
    };
}
