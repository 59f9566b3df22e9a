namespace OperatorPanel.Core.Audit;

/// <summary>Nothing recorded: a project without a historian (not saved yet), and tests that do not look.</summary>
public sealed class NoAuditTrail : IAuditTrail
{
    public static NoAuditTrail Instance { get; } = new();

    private NoAuditTrail()
    {
    }

    public void Record(AuditEntry entry)
    {
    }
}
