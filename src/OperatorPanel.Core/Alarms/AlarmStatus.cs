using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Alarms;

/// <summary>The current standing of one alarm of the project.</summary>
/// <param name="StationName">The project's name of the station the flag belongs to.</param>
/// <param name="Station">The station's bus address.</param>
/// <param name="Definition">Flag, text, class and whether it must be acknowledged.</param>
/// <param name="State">Where the alarm stands.</param>
/// <param name="RaisedAt">When it was last raised; null if never.</param>
/// <param name="ClearedAt">When it last cleared after that raise; null while active or if never raised.</param>
/// <param name="AcknowledgedAt">When the operator acknowledged the last raise; null if not (yet).</param>
public sealed record AlarmStatus(
    string StationName,
    Station Station,
    AlarmDefinition Definition,
    AlarmState State,
    DateTimeOffset? RaisedAt,
    DateTimeOffset? ClearedAt,
    DateTimeOffset? AcknowledgedAt)
{
    /// <summary>
    /// True while the flag's latest reading is good. False before the first read and while the station is offline or
    /// refuses the read: <see cref="State"/> is then the last known state, not the present one.
    /// </summary>
    public bool IsKnown { get; init; }

    public bool IsActive => State is AlarmState.ActiveUnacknowledged or AlarmState.ActiveAcknowledged;

    public bool IsUnacknowledged => State is AlarmState.ActiveUnacknowledged or AlarmState.ClearedUnacknowledged;

    /// <summary>Shown in the alarm list: active, or cleared but still waiting for the operator.</summary>
    public bool IsPending => State != AlarmState.Cleared;
}
