using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Polling;

/// <summary>What the bus knows about one station's link (Polling/StationTracker), for the status bar and diagnostics.</summary>
/// <param name="Station">The station.</param>
/// <param name="State">Online, offline, or unknown before the first exchange.</param>
/// <param name="LastError">The latest failure or refusal, kept after recovery so the user can read it; null if none yet.</param>
/// <param name="ConsecutiveFailures">Exchanges without a valid reply since the last one that had one.</param>
/// <param name="LastReplyAt">Time of the last valid reply.</param>
/// <param name="LastFailureAt">Time of the last exchange that brought no valid reply.</param>
/// <param name="NextTryAt">For a silent station resting between tries (PollingOptions.OfflineRetryInterval), when it is tried next; else null.</param>
/// <param name="LastErrorKind">The kind of the latest link failure, so a front end can say what to check; null for a refusal or none.</param>
public sealed record StationStatus(
    Station Station,
    StationState State,
    string? LastError,
    int ConsecutiveFailures,
    DateTimeOffset? LastReplyAt,
    DateTimeOffset? LastFailureAt = null,
    DateTimeOffset? NextTryAt = null,
    PlcErrorKind? LastErrorKind = null)
{
    public static StationStatus Initial(Station station) => new(station, StationState.Unknown, null, 0, null);
}
