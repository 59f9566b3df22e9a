using OperatorPanel.Core.Audit;

namespace OperatorPanel.Core.Writes;

/// <summary>A write or STOP an earlier program left without outcome (<paramref name="Intent"/>) and how this start settled it.</summary>
public sealed record CutShortWrite(AuditEntry Intent, AuditEntry Resolution)
{
    /// <summary>
    /// "a write cut short earlier (its program ended before the outcome): station 2 VW200: 16#0000 -> 16#0002 by root at
    /// 2026-11-27T16:38:02.987Z; resolved at start: applied: the PLC holds the requested 16#0002".
    /// </summary>
    public string Describe() =>
        $"{(Intent.Action == AuditAction.Stop ? "a STOP" : "a write")} cut short earlier (its program ended before the outcome): "
        + $"{Intent.Describe()} by {Intent.User} at {Alarms.AlarmTime.Format(Intent.At)}; resolved at start: {Resolution.Outcome}: {Resolution.Detail}";
}
