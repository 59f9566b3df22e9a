namespace OperatorPanel.Core.Audit;

/// <summary>
/// A record keeper of writes and STOPs: the write journal, a historian. The one interface every front end hands its
/// polling engines and STOPs (<see cref="AuditContext"/>), so nothing changes a PLC off the record.
/// </summary>
public interface IAuditTrail
{
    /// <summary>
    /// Puts <paramref name="entry"/> on record. An intent's frame waits for this: when the task ends the entry must be
    /// kept even if the program is killed next. Returns null when recorded, otherwise why not (then the action is not sent).
    /// </summary>
    ValueTask<string?> RecordAsync(AuditEntry entry, CancellationToken cancellationToken);
}
