namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Interrupt events: a queue per priority group (communications, I/O, timed), first come first served within a
/// group, one routine at a time and never pre-empted (docs/sources/s7200-facts.md section 5). Queue depths 4/16/8,
/// communications 8 on CPU 224XP/226; a full queue sets SM4.0/SM4.1/SM4.2 and the event is lost.
/// </summary>
public sealed partial class StlPlc
{
    private readonly List<StlQueuedEvent>[] _queues = [[], [], []];
    private readonly int[] _attached = new int[34];
    private readonly long[] _timedInterval = new long[2];
    private readonly long[] _timedNext = new long[2];
    private readonly List<StlEvent> _raised = [];
    private readonly uint[] _interruptedAc = new uint[4];
    private int[] _capacity = [];
    private int _queued;
    private bool _interruptsEnabled;
    private int _interruptBase = -1;
    private StlQueuedEvent _running;
    private long _runningStart;
    private byte _interruptedSmb1;
    private long _runningInstructions;
    private int _interruptedLine;
    private long _nextChange = long.MaxValue;

    private void InitialiseQueues()
    {
        _capacity = [Cpu.CommunicationPorts > 1 ? 8 : 4, 16, 8];
        ResetInterrupts();
    }

    private void ResetInterrupts()
    {
        Array.Fill(_attached, -1);
        Array.Fill(_timedNext, long.MaxValue);
        foreach (var queue in _queues)
        {
            queue.Clear();
        }

        _queued = 0;
        EnableInterrupts(false);
    }

    private static int GroupOf(int number) => number switch
    {
        8 or 9 or 23 or 24 or 25 or 26 => 0,
        10 or 11 or 21 or 22 => 2,
        _ => 1,
    };

    private void EnableInterrupts(bool enabled)
    {
        _interruptsEnabled = enabled;
        Memory.SM[4] = (byte)(enabled ? Memory.SM[4] | 0x10 : Memory.SM[4] & ~0x10);
    }

    /// <summary>ATCH; for the timed events 10/11 the interval in SMB34/SMB35 (1-255 ms) is captured now.</summary>
    private void Attach(int block, int number)
    {
        _attached[number] = block;
        if (number is 10 or 11)
        {
            var interval = Memory.SM[34 + number - 10] * Millisecond;
            _timedInterval[number - 10] = interval;
            _timedNext[number - 10] = interval > 0 ? _now + interval : long.MaxValue;
            _nextChange = Math.Min(_nextChange, _timedNext[number - 10]);
        }
    }

    private void Detach(int number)
    {
        _attached[number] = -1;
        if (number is 10 or 11)
        {
            _timedNext[number - 10] = long.MaxValue;
        }
    }

    private void Enqueue(int number, long at)
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
            Memory.SM[4] |= (byte)(1 << group);
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

    private void StartInterrupt()
    {
        var queue = _queues.First(q => q.Count > 0);
        _running = queue[0];
        queue.RemoveAt(0);
        _queued--;
        _now += StlTiming.InterruptOverhead;
        _busy += StlTiming.InterruptOverhead;
        _runningStart = _now;
        _runningInstructions = InstructionsExecuted;
        _interruptedLine = NextMainLine();

        // The CPU saves the accumulators and the instruction status bits (SMB1) around every interrupt routine, as it
        // saves the logic stack (System Manual, "System Support for Interrupts", Table 6-47); interrupts never nest.
        Array.Copy(_ac, _interruptedAc, _ac.Length);
        _interruptedSmb1 = Memory.SM[1];
        Push(_program.Blocks[_running.Block], InterruptLBase, null);
        _interruptBase = _depth;
    }

    private void FinishInterrupt()
    {
        _interruptBase = -1;
        Array.Copy(_interruptedAc, _ac, _ac.Length);
        Memory.SM[1] = _interruptedSmb1;
        for (var group = 0; group < _queues.Length; group++)
        {
            if (_queues[group].Count == 0)
            {
                Memory.SM[4] &= (byte)~(1 << group);
            }
        }

        InterruptServed?.Invoke(this, new StlInterruptRun(
            _program.Blocks[_running.Block].Name, _running.Event, TimeSpan.FromTicks(_running.At / 100),
            TimeSpan.FromTicks(_runningStart / 100), TimeSpan.FromTicks(_now / 100), InstructionsExecuted - _runningInstructions, _interruptedLine));
    }

    /// <summary>The .awl line the main program goes on at; 0 outside OB1 and its subroutines.</summary>
    private int NextMainLine()
    {
        if (_depth < 0)
        {
            return 0;
        }

        var frame = _frames[_depth];
        return frame.Pc < frame.Block.Ops.Length ? frame.Block.Ops[frame.Pc].Line : 0;
    }
}
