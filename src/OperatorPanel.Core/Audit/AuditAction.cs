namespace OperatorPanel.Core.Audit;

/// <summary>What the panel did to the PLC.</summary>
public enum AuditAction
{
    /// <summary>A value written to an output or memory cell.</summary>
    Write,

    /// <summary>The PLC put into STOP (docs/protocol-v2.md, "07 STOP").</summary>
    Stop,
}
