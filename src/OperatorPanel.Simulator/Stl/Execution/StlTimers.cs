using OperatorPanel.Simulator.Stl.Operations;

namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// T0-T255 and TON, TONR and TOF (System Manual C79000-G7076-C233-01 p. 9-16, Table 9-1; ML801761 = manualslib 801761
/// p. 211-212, printed 197-198, Table 6-74; "Timer Instructions"). The timer number fixes the resolution: TONR T0/T64
/// 1 ms, T1-T4/T65-T68 10 ms, T5-T31/T69-T95 100 ms; TON/TOF T32/T96 1 ms, T33-T36/T97-T100 10 ms, T37-T63/T101-T255
/// 100 ms. The current value counts to 32767 at most. How each resolution is updated (ML801761 printed p. 198,
/// "Understanding How Resolution Affects the Timer Action"): 1 ms timers every millisecond, asynchronously to the scan
/// (here: whenever the timer is read or executed); 10 ms timers at the start of each scan, so bit and value stay
/// constant through a scan; 100 ms timers when their instruction executes, by the 100 ms intervals elapsed since its
/// previous execution. The part of an interval not yet counted is carried to the next update, so no time is lost or
/// invented.
/// </summary>
internal sealed class StlTimers(StlTime time)
{
    private const short MaxValue = 32767;

    /// <summary>The 10 ms timers, updated at the start of each scan.</summary>
    private static readonly int[] TenMillisecondTimers = [1, 2, 3, 4, 33, 34, 35, 36, 65, 66, 67, 68, 97, 98, 99, 100];

    private readonly StlTimer[] _timers = new StlTimer[256];

    /// <summary>Resolution of a timer number in ms (Table 9-1; the same on CPU 221-226).</summary>
    public static int ResolutionOf(int timer) => timer switch
    {
        0 or 64 or 32 or 96 => 1,
        (>= 1 and <= 4) or (>= 65 and <= 68) or (>= 33 and <= 36) or (>= 97 and <= 100) => 10,
        _ => 100,
    };

    /// <summary>TONR numbers: T0-T31 and T64-T95; TON and TOF use T32-T63 and T96-T255.</summary>
    public static bool IsRetentive(int timer) => timer < 32 || (timer >= 64 && timer < 96);

    /// <summary>The current value as the program reads it now (a 1 ms timer counts on the way).</summary>
    public short Value(int timer)
    {
        CountAsynchronous(timer);
        return _timers[timer].Value;
    }

    public bool Bit(int timer)
    {
        CountAsynchronous(timer);
        return _timers[timer].Bit;
    }

    /// <summary>A word written to Tn (MOVW 5, T37): the current value, kept within 0-32767.</summary>
    public void SetValue(int timer, short value) => _timers[timer].Value = Math.Clamp(value, (short)0, MaxValue);

    /// <summary>S Tn: the bit only.</summary>
    public void SetBit(int timer) => _timers[timer].Bit = true;

    /// <summary>R Tn: bit off, current value 0, timing stops (an enabled TON starts again from 0 on its next execution).</summary>
    public void Reset(int timer)
    {
        ref var t = ref _timers[timer];
        (t.Value, t.Bit, t.Running) = (0, false, false);
    }

    /// <summary>At the start of each scan.</summary>
    public void CountTenMillisecondTimers()
    {
        foreach (var timer in TenMillisecondTimers)
        {
            Count(timer);
        }
    }

    /// <summary>TON/TONR/TOF Txxx, PT with IN = <paramref name="input"/> (the top of the logic stack).</summary>
    public void Execute(int timer, StlOpCode kind, short preset, bool input)
    {
        ref var t = ref _timers[timer];
        t.Kind = kind;
        t.Preset = preset;
        switch (kind)
        {
            case StlOpCode.Ton when !input:
                (t.Value, t.Bit, t.Running) = (0, false, false);
                break;
            case StlOpCode.Ton or StlOpCode.Tonr when input:
                Start(ref t, fromZero: kind == StlOpCode.Ton);
                CountOnExecution(timer);
                break;
            case StlOpCode.Tonr:
                CountOnExecution(timer);
                t.Running = false;
                break;
            case StlOpCode.Tof:
                TimeOff(timer, ref t, input);
                break;
        }

        t.LastInput = input;
    }

    private void CountAsynchronous(int timer)
    {
        if (ResolutionOf(timer) == 1)
        {
            Count(timer);
        }
    }

    /// <summary>Adds the whole intervals elapsed since the reference, then applies the timer bit rule of its kind.</summary>
    private void Count(int timer)
    {
        ref var t = ref _timers[timer];
        if (!t.Running)
        {
            return;
        }

        var interval = ResolutionOf(timer) * StlTime.Millisecond;
        var ticks = (time.Now - t.Reference) / interval;
        if (ticks > 0)
        {
            t.Reference += ticks * interval;
            t.Value = (short)Math.Min(MaxValue, t.Value + ticks);
        }

        if (t.Kind == StlOpCode.Tof)
        {
            if (t.Value >= t.Preset)
            {
                (t.Value, t.Bit, t.Running) = (t.Preset, false, false);
            }
        }
        else
        {
            t.Bit = t.Value >= t.Preset;
        }
    }

    private void Start(ref StlTimer t, bool fromZero)
    {
        if (!t.Running)
        {
            t.Running = true;
            t.Reference = time.Now;
            t.Value = fromZero ? (short)0 : t.Value;
        }
    }

    /// <summary>TOF: IN on sets the bit and clears the value; IN falling starts timing; at PT the bit goes off.</summary>
    private void TimeOff(int timer, ref StlTimer t, bool input)
    {
        if (input)
        {
            (t.Value, t.Bit, t.Running) = (0, true, false);
            return;
        }

        if (t.LastInput && t.Bit)
        {
            (t.Value, t.Running, t.Reference) = (0, true, time.Now);
        }

        CountOnExecution(timer);
    }

    /// <summary>A 100 ms timer counts when its instruction executes, a 1 ms timer whenever it is looked at; a 10 ms timer waits for the next scan.</summary>
    private void CountOnExecution(int timer)
    {
        if (ResolutionOf(timer) != 10)
        {
            Count(timer);
        }
        else if (_timers[timer].Kind != StlOpCode.Tof)
        {
            _timers[timer].Bit = _timers[timer].Value >= _timers[timer].Preset;
        }
    }
}
