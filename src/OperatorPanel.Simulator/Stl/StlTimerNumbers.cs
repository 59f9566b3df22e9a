using OperatorPanel.Simulator.Stl.Execution;
using OperatorPanel.Simulator.Stl.Operations;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Timer numbers, checked over the whole program (C79000-G7076-C233-01 p. 9-16, Table 9-1 and its note): TONR takes a
/// retentive timer number (T0-T31, T64-T95) and TON/TOF a non-retentive one, and one timer number is never both a TON
/// and a TOF. The operand kinds of every instruction are checked before, by the Core instruction table.
/// </summary>
internal sealed class StlTimerNumbers
{
    private readonly Dictionary<int, StlOpCode> _timerKinds = [];

    public bool Check(StlOp op, Action<int, string> report)
    {
        var refusal = op.Code is StlOpCode.Ton or StlOpCode.Tonr or StlOpCode.Tof ? TimerKind(op) : null;
        if (refusal is not null)
        {
            report(op.Line, $"{op.Mnemonic}: {refusal}");
        }

        return refusal is null;
    }

    private string? TimerKind(StlOp op)
    {
        var timer = op.A!.Offset;
        if (StlTimers.IsRetentive(timer) != (op.Code == StlOpCode.Tonr))
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
