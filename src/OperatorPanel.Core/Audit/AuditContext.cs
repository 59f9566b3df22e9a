namespace OperatorPanel.Core.Audit;

/// <summary>What a bus's engine and its STOPs stamp on their audit entries: where they go, the bus's port, the user.</summary>
/// <param name="Trail">The record keeper (the write journal, maybe with a historian).</param>
/// <param name="Port">The bus's serial port as the link names it.</param>
/// <param name="User">The OS user running the panel (<see cref="AuditUser.Current"/>).</param>
public sealed record AuditContext(IAuditTrail Trail, string Port, string User);
