using OperatorPanel.Core.Polling;

namespace OperatorPanel.Core.Alarms;

/// <summary>
/// What a polled flag says about its alarm. Only a <see cref="ValueQuality.Good"/> reading says anything: a flag never
/// read, refused, or stale because the station stopped answering is unknown, never "not set" (an operator must not read
/// a dead link as all clear).
/// </summary>
public static class AlarmFlag
{
    /// <summary>True set, false not set, null unknown.</summary>
    public static bool? Reading(PolledValue? value) =>
        value is { Quality: ValueQuality.Good, AsBit: { } on } ? on : null;
}
