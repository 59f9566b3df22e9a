namespace OperatorPanel.Core.Alarms;

/// <summary>What happened to an alarm; one history entry per transition.</summary>
public enum AlarmTransition
{
    /// <summary>The flag bit was read as 1 after being 0 (or never read).</summary>
    Raised,

    /// <summary>The operator acknowledged it.</summary>
    Acknowledged,

    /// <summary>The flag bit was read as 0 after being 1.</summary>
    Cleared,
}
