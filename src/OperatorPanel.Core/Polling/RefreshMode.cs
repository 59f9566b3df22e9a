namespace OperatorPanel.Core.Polling;

/// <summary>The two modes of seed 000 §7.</summary>
public enum RefreshMode
{
    /// <summary>Poll cycle after cycle, as fast as the link allows but never sooner than the minimum period.</summary>
    Continuous,

    /// <summary>The triggered mode: nothing is read until a refresh is requested, then one full cycle runs.</summary>
    OnDemand,
}
