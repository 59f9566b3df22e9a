namespace OperatorPanel.Core.Audit;

/// <summary>
/// Where the panel's actions on a PLC are recorded for later (the historian's audit table): each write and each STOP
/// twice, its intent before it is sent and its outcome after (<see cref="AuditEntry"/>). Implementations never throw and
/// never block: the caller is on its way to the wire.
/// </summary>
public interface IAuditTrail
{
    void Record(AuditEntry entry);
}
