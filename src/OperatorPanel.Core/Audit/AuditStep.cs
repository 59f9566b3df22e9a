namespace OperatorPanel.Core.Audit;

/// <summary>Where an audited action stands.</summary>
public enum AuditStep
{
    /// <summary>About to be sent; on record before the frame leaves the PC.</summary>
    Intent,

    /// <summary>What became of it, as the panel judged it when it ended.</summary>
    Outcome,

    /// <summary>
    /// Its program ended (Ctrl+C, killed, crashed) before the outcome: found at a later start and settled by reading the
    /// target back (applied, not applied, unknown).
    /// </summary>
    ResolvedAtStart,
}
