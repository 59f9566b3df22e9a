using OperatorPanel.Core.Audit;

namespace OperatorPanel.Core.Writes;

/// <summary>A write's audit entries (<see cref="AuditEntry"/>): its intent before the frame leaves, its outcome after.</summary>
public static class WriteAudit
{
    public static AuditEntry Intent(WriteRequest request, string oldValue, AuditContext context, DateTimeOffset at)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentNullException.ThrowIfNull(context);
        return new AuditEntry(
            Guid.NewGuid(), AuditStep.Intent, AuditAction.Write, at, context.User, context.Port, request.Station,
            request.Address.ToString(), request.Symbol, oldValue, WriteLog.Format(request.Address, request.Value));
    }

    /// <summary>The outcome in the words <c>opanel write</c> prints: "confirmed", "read back differently", "not applied"...</summary>
    public static AuditEntry Outcome(AuditEntry intent, WriteRequest request, WriteOutcome outcome, DateTimeOffset at)
    {
        ArgumentNullException.ThrowIfNull(intent);
        ArgumentNullException.ThrowIfNull(request);
        var (words, detail) = outcome switch
        {
            WriteOutcome.Confirmed => ("confirmed", null),
            WriteOutcome.ReadBackMismatch m => ("read back differently", $"read back {WriteLog.Format(request.Address, m.ReadBack)}"),
            WriteOutcome.ConfirmedByReadBack c => ("confirmed (reply lost, read back)", c.Cause),
            WriteOutcome.NotApplied n => ("not applied", $"{n.Cause}; read back {WriteLog.Format(request.Address, n.ReadBack)}"),
            WriteOutcome.Unknown u => ("unknown", $"{u.Cause}; {u.Detail}"),
            WriteOutcome.Failed f => ("failed, nothing written", f.Reason),
            _ => throw new ArgumentOutOfRangeException(nameof(outcome), outcome, null),
        };
        return intent.Then(AuditStep.Outcome, at, words, detail);
    }
}
