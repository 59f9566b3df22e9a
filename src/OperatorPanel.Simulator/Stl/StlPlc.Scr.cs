namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Sequence control relays (A5E00307987-04 chapter 6, "Sequence Control Relay (SCR) Instructions"); where they may be
/// written is the Core instruction table's rule.
/// LSCR S_bit loads the S bit onto the logic stack and, when it is 0, skips the segment to its SCRE; SCRT S_bit (with
/// power flow) sets the referenced S bit and resets the S bit of the active segment; CSCRE (with power flow) ends the
/// segment here; SCRE marks its end.
/// </summary>
public sealed partial class StlPlc
{
    private StlLoc? _activeScr;

    private void LoadScr(StlOp op)
    {
        var active = ReadBit(op.A!);
        _stack = active ? 1u : 0u;
        _activeScr = op.A;
        if (!active)
        {
            _frames[_depth].Pc = op.N;
        }
    }

    private void TransitionScr(StlOp op)
    {
        WriteBit(op.A!, true);
        if (_activeScr is not null && !(_activeScr.Offset == op.A!.Offset && _activeScr.Bit == op.A.Bit))
        {
            WriteBit(_activeScr, false);
        }
    }
}
