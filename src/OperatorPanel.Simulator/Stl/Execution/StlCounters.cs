using OperatorPanel.Simulator.Stl.Operations;

namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// C0-C255 and CTU, CTD and CTUD (System Manual C79000-G7076-C233-01 p. 9-24, "Understanding the S7-200 Counter
/// Instructions"; A5E00307987-04 chapter 6, "Counter Instructions"). In STL the inputs are stack levels: CTU R on top,
/// CU second; CTD LD on top, CD second; CTUD R on top, CD second, CU third. Counts happen on the rising edge of a count
/// input as the counter last saw it. CTU stops at 32767; CTUD wraps 32767 -> -32768 and back; CTD stops at 0. The
/// counter bit is current &gt;= PV for CTU and CTUD, current = 0 for CTD; R Cn (or the reset input) clears value and
/// bit, CTD's LD loads PV and clears the bit. After the box the count inputs' levels are popped, leaving the top level
/// (unconfirmed: the manual does not say; Micro/WIN ends a network after a counter box).
/// </summary>
internal sealed class StlCounters
{
    private readonly StlCounter[] _counters = new StlCounter[256];

    public short Value(int counter) => _counters[counter].Value;

    public bool Bit(int counter) => _counters[counter].Bit;

    /// <summary>A word written to Cn (MOVW 5, C1): the current value.</summary>
    public void SetValue(int counter, short value) => _counters[counter].Value = value;

    /// <summary>S Cn sets the bit only; R Cn clears bit and value.</summary>
    public void WriteBit(int counter, bool value)
    {
        ref var c = ref _counters[counter];
        (c.Value, c.Bit) = value ? (c.Value, true) : ((short)0, false);
    }

    /// <summary>CTU/CTD/CTUD Cxxx, PV: reads its inputs from the logic stack and pops the count inputs' levels.</summary>
    public void Execute(int counter, StlOpCode kind, short preset, StlLogicStack logic)
    {
        ref var c = ref _counters[counter];
        var top = logic.Top;
        var second = logic.Level(1);
        var third = logic.Level(2);
        switch (kind)
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

                logic.Bits = (logic.Bits >> 1) | (top ? 1u : 0u);
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

                logic.Bits = (logic.Bits >> 1) | (top ? 1u : 0u);
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

                logic.Bits = ((logic.Bits >> 2) & ~1u) | (top ? 1u : 0u);
                break;
        }
    }

    private static bool Rising(ref bool last, bool now)
    {
        var rising = now && !last;
        last = now;
        return rising;
    }
}
