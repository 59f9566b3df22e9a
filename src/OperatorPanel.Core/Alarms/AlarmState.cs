namespace OperatorPanel.Core.Alarms;

/// <summary>
/// Where one alarm stands. An alarm that must be acknowledged (<see cref="AlarmDefinition.AcknowledgementRequired"/>)
/// leaves the list only once it is both cleared and acknowledged, whichever comes first.
/// </summary>
public enum AlarmState
{
    /// <summary>Flag off and nothing left to acknowledge: not shown as pending.</summary>
    Cleared,

    /// <summary>Flag on, the operator has not acknowledged it yet.</summary>
    ActiveUnacknowledged,

    /// <summary>Flag on, acknowledged (or an alarm that needs no acknowledgement).</summary>
    ActiveAcknowledged,

    /// <summary>Flag back off, but the operator has not acknowledged it yet.</summary>
    ClearedUnacknowledged,
}
