namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// CTU, CTD and CTUD (System Manual C79000-G7076-C233-01 p. 9-24, "Understanding the S7-200 Counter Instructions";
/// A5E00307987-04 chapter 6, "Counter Instructions"). In STL the inputs are stack levels: CTU R on top, CU second;
/// CTD LD on top, CD second; CTUD R on top, CD second, CU third. Counts happen on the rising edge of a count input as
/// the counter last saw it. CTU stops at 32767; CTUD wraps 32767 -> -32768 and back; CTD stops at 0. The counter bit
/// is current &gt;= PV for CTU and CTUD, current = 0 for CTD; R Cn (or the reset input) clears value and bit, CTD's LD
/// loads PV and clears the bit. After the box the count inputs' levels are popped, leaving the top level
/// (unconfirmed: the manual does not say; Micro/WIN ends a network after a counter box).
/// </summary>
public sealed partial class StlPlc
{
    private readonly StlCounter[] _counters = new StlCounter[256];

    private void Counter(StlOp op)
    {
        ref var c = ref _counters[op.A!.Offset];
        var preset = (short)Read(op.B!, 2);
        var top = Top;
        var second = ((_stack >> 1) & 1) != 0;
        var third = ((_stack >> 2) & 1) != 0;
        switch (op.Code)
        {
            case StlOpCode.Ctu:
                var up = Rising(ref c.LastUp, second);
                if (top)
                {
                    (c.Value, c.Bit) = (0, false);
                }
                else
                {
                    c.Value = (short)(up && c.Value < short.MaxValue ? c.Value + 1 : c.Value);
                    c.Bit = c.Value >= preset;
                }

                _stack = (_stack >> 1) | (top ? 1u : 0u);
                break;
            case StlOpCode.Ctd:
                var down = Rising(ref c.LastDown, second);
                if (top)
                {
                    (c.Value, c.Bit) = (preset, false);
                }
                else
                {
                    c.Value = (short)(down && c.Value > 0 ? c.Value - 1 : c.Value);
                    c.Bit = c.Value == 0;
                }

                _stack = (_stack >> 1) | (top ? 1u : 0u);
                break;
            case StlOpCode.Ctud:
                var countUp = Rising(ref c.LastUp, third);
                var countDown = Rising(ref c.LastDown, second);
                if (top)
                {
                    (c.Value, c.Bit) = (0, false);
                }
                else
                {
                    c.Value = unchecked((short)(c.Value + (countUp ? 1 : 0) - (countDown ? 1 : 0)));
                    c.Bit = c.Value >= preset;
                }

                _stack = ((_stack >> 2) & ~1u) | (top ? 1u : 0u);
                break;
        }
    }

    private static bool Rising(ref bool last, bool now)
    {
        var rising = now && !last;
        last = now;
        return rising;
    }

    /// <summary>R Tn/Cn clears bit and value (and stops a timer); S sets the bit only.</summary>
    private void WriteTimerOrCounterBit(StlLoc loc, bool value)
    {
        if (loc.Kind == StlLocKind.Timer)
        {
            if (value)
            {
                _timers[loc.Offset].Bit = true;
            }
            else
            {
                ResetTimer(loc.Offset);
            }
        }
        else
        {
            ref var c = ref _counters[loc.Offset];
            (c.Value, c.Bit) = value ? (c.Value, true) : ((short)0, false);
        }
    }
}
