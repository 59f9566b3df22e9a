using System.Collections.Immutable;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Stop;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Core.Audit;

/// <summary>
/// Builds the audit's entries for a write and a STOP, with the values printed as <see cref="WriteLog"/> prints them, so
/// the audit and the log say the same thing in the same words.
/// </summary>
public static class AuditEntries
{
    private static long _lastOperation;

    /// <summary>A new operation number for an intent and its outcome.</summary>
    public static long NextOperation() => Interlocked.Increment(ref _lastOperation);

    public static AuditEntry WriteIntent(long operation, DateTimeOffset at, WriteRequest request, ImmutableArray<byte> oldValue, string user)
    {
        ArgumentNullException.ThrowIfNull(request);
        return new AuditEntry(
            at, operation, AuditAction.Write, AuditPhase.Intent, request.Station, request.Address,
            WriteLog.Format(request.Address, oldValue), WriteLog.Format(request.Address, request.Value), null, string.Empty, user);
    }

    public static AuditEntry WriteResult(AuditEntry intent, DateTimeOffset at, WriteOutcome outcome)
    {
        ArgumentNullException.ThrowIfNull(intent);
        ArgumentNullException.ThrowIfNull(outcome);
        var address = intent.Address!.Value;
        var (word, detail) = outcome switch
        {
            Writes.WriteOutcome.Confirmed => ("confirmed", string.Empty),
            Writes.WriteOutcome.ReadBackMismatch m => ("readBackMismatch", "read back " + WriteLog.Format(address, m.ReadBack)),
            Writes.WriteOutcome.ConfirmedByReadBack c => ("confirmedByReadBack", c.Cause),
            Writes.WriteOutcome.NotApplied n => ("notApplied", $"read back {WriteLog.Format(address, n.ReadBack)}: {n.Cause}"),
            Writes.WriteOutcome.Unknown u => ("unknown", $"{u.Cause}; {u.Detail}"),
            Writes.WriteOutcome.Failed f => ("failed", $"{JsonWords.Of(f.Kind)}: {f.Reason}"),
            _ => throw new ArgumentOutOfRangeException(nameof(outcome), outcome, null),
        };
        return intent with { At = at, Phase = AuditPhase.Outcome, Outcome = word, Detail = detail };
    }

    /// <summary>The caller withdrew the write while it was still queued: nothing was sent (Core/Writes/PendingWrite).</summary>
    public static AuditEntry Withdrawn(AuditEntry intent, DateTimeOffset at)
    {
        ArgumentNullException.ThrowIfNull(intent);
        return intent with { At = at, Phase = AuditPhase.Outcome, Outcome = "withdrawn", Detail = "cancelled before it was sent; nothing written" };
    }

    public static AuditEntry StopIntent(long operation, DateTimeOffset at, Addressing.Station station, string user) =>
        new(at, operation, AuditAction.Stop, AuditPhase.Intent, station, null, "RUN", "STOP", null, string.Empty, user);

    public static AuditEntry StopResult(AuditEntry intent, DateTimeOffset at, StopOutcome outcome)
    {
        ArgumentNullException.ThrowIfNull(intent);
        ArgumentNullException.ThrowIfNull(outcome);
        return intent with { At = at, Phase = AuditPhase.Outcome, Outcome = JsonWords.Of(outcome.Verdict), Detail = outcome.Text };
    }
}
