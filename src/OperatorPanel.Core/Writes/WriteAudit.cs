using OperatorPanel.Core.Audit;
using Serilog;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// A write's audit entries (<see cref="AuditEntry"/>): its intent before the frame leaves, its outcome after. The polling
/// loop's write job (Polling/PollingEngine, the one place every write of every writer passes) records both.
/// </summary>
public static class WriteAudit
{
    /// <summary>
    /// Puts the intent on record in <paramref name="audit"/>'s trail before the write is handed to its writer. Returns the
    /// intent (null without audit) or, when it could not be recorded, the write's refusal: it is then not sent.
    /// </summary>
    public static async Task<(AuditEntry? Intent, WriteOutcome? NotRecorded)> RecordIntentAsync(AuditContext? audit, WriteRequest request, string oldValue, DateTimeOffset at)
    {
        if (audit is null)
        {
            return (null, null);
        }

        var intent = Intent(request, oldValue, audit, at);
        return await audit.Trail.RecordAsync(intent, CancellationToken.None).ConfigureAwait(false) is { } notKept
            ? (null, new WriteOutcome.Failed($"the write was not sent: it could not be put on record ({notKept})", WriteFailureKind.NotRecorded))
            : (intent, null);
    }

    /// <summary>
    /// Puts the outcome of a write whose <paramref name="intent"/> is on record there too, before its caller hears it; a
    /// failure to is logged (the write has happened: the intent stays, and a later start settles it).
    /// </summary>
    public static async Task RecordOutcomeAsync(AuditContext? audit, AuditEntry? intent, WriteRequest request, WriteOutcome outcome, DateTimeOffset at, ILogger logger)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentNullException.ThrowIfNull(logger);
        if (audit is not null && intent is not null
            && await audit.Trail.RecordAsync(Outcome(intent, request, outcome, at), CancellationToken.None).ConfigureAwait(false) is { } notKept)
        {
            logger.Warning("Write {Request}: its outcome could not be put on record: {Reason:l}", request.ToString(), notKept);
        }
    }

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
