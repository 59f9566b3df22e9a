namespace OperatorPanel.Core.Audit;

/// <summary>Each action is recorded twice: what was meant before anything is sent, what became of it after.</summary>
public enum AuditPhase
{
    Intent,
    Outcome,
}
