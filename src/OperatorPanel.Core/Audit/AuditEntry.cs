using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Audit;

/// <summary>One line of the audit: an action's intent or its outcome.</summary>
/// <param name="At">When (UTC, from the caller's TimeProvider).</param>
/// <param name="Operation">Pairs an intent with its outcome; unique within one run of the program.</param>
/// <param name="Action">Write or STOP.</param>
/// <param name="Phase">Intent (before sending) or outcome.</param>
/// <param name="Station">The station acted on.</param>
/// <param name="Address">The written address; null for a STOP.</param>
/// <param name="OldValue">The last polled value as the write log prints it (16#002A, 0/1, "unknown"); "RUN" for a STOP.</param>
/// <param name="NewValue">The value written; "STOP" for a STOP.</param>
/// <param name="Outcome">Null for an intent; the outcome's word ("confirmed", "readBackMismatch", "stopped"...).</param>
/// <param name="Detail">The outcome in the panel's words (read-back value, reason); empty for an intent.</param>
/// <param name="User">Who acted: the Windows user of the panel, "opanel" for the CLI.</param>
public sealed record AuditEntry(
    DateTimeOffset At,
    long Operation,
    AuditAction Action,
    AuditPhase Phase,
    Station Station,
    PlcAddress? Address,
    string OldValue,
    string NewValue,
    string? Outcome,
    string Detail,
    string User);
