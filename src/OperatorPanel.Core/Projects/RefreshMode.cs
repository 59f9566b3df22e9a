namespace OperatorPanel.Core.Projects;

/// <summary>When the panel reads the configured variables (seed 000 §7).</summary>
public enum RefreshMode
{
    /// <summary>Permanent monitoring: poll again as soon as a cycle ends, but not faster than the minimum period.</summary>
    Continuous,

    /// <summary>The paper's "triggered mode": read only when the operator asks, to load the PLC less.</summary>
    OnDemand,
}
