namespace OperatorPanel.Core.Audit;

/// <summary>What the panel did to a PLC.</summary>
public enum AuditAction
{
    /// <summary>A write of an output or memory cell (Core/Writes).</summary>
    Write,

    /// <summary>A remote STOP (Core/Stop, docs/protocol.md "07 STOP").</summary>
    Stop,
}
