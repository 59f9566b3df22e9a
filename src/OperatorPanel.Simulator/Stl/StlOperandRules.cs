using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Operand rules past width and range, checked once over the whole program (A5E00307987-04 chapter 6 operand tables;
/// C79000-G7076-C233-01 p. 9-16, Table 9-1): immediate contacts read I only, immediate outputs write Q only, BIR reads
/// an IB, BIW writes a QB, SCR instructions take S bits, TONR takes a retentive timer number (T0-T31, T64-T95) and
/// TON/TOF a non-retentive one, and one timer number is never both a TON and a TOF.
/// </summary>
internal sealed class StlOperandRules
{
    private readonly Dictionary<int, StlOpCode> _timerKinds = [];

    public bool Check(StlOp op, Action<int, string> report)
    {
        var refusal = op.Code switch
        {
            StlOpCode.Ldi or StlOpCode.Ldni or StlOpCode.Ai or StlOpCode.Ani or StlOpCode.Oi or StlOpCode.Oni or StlOpCode.Bir =>
                InArea(op.A, MemoryArea.I, "an input (I) the immediate read takes"),
            StlOpCode.AssignI or StlOpCode.SetI or StlOpCode.ResetI => InArea(op.A, MemoryArea.Q, "an output (Q) the immediate write takes"),
            StlOpCode.Biw => InArea(op.B, MemoryArea.Q, "an output byte (QB) BIW writes"),
            StlOpCode.Lscr or StlOpCode.Scrt => InArea(op.A, MemoryArea.S, "an S bit"),
            StlOpCode.Ton or StlOpCode.Tonr or StlOpCode.Tof => TimerKind(op),
            _ => null,
        };
        if (refusal is not null)
        {
            report(op.Line, $"{op.Mnemonic}: {refusal}");
        }

        return refusal is null;
    }

    private static string? InArea(StlLoc? loc, MemoryArea area, string what) =>
        loc is { Kind: StlLocKind.Direct } && loc.Area == (int)area ? null : $"the operand must be {what}";

    private string? TimerKind(StlOp op)
    {
        var timer = op.A!.Offset;
        if (StlPlc.IsRetentiveTimer(timer) != (op.Code == StlOpCode.Tonr))
        {
            return op.Code == StlOpCode.Tonr
                ? $"T{timer} is a TON/TOF timer; TONR takes T0-T31 or T64-T95"
                : $"T{timer} is a TONR timer; {op.Mnemonic} takes T32-T63 or T96-T255";
        }

        if (_timerKinds.TryGetValue(timer, out var kind) && kind != op.Code)
        {
            return $"T{timer} is already used as a {kind.ToString().ToUpperInvariant()}; TON and TOF cannot share a timer number";
        }

        _timerKinds[timer] = op.Code;
        return null;
    }
}
