using OperatorPanel.Core.Alarms;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// The order of the alarm list, so that what needs the operator is never below the fold: first by state (active
/// unacknowledged, active acknowledged, cleared unacknowledged, then the rest), then by class (fault, warning,
/// information), then the latest raised first, then project order. Alarm summaries of HMIs sort the same way
/// (unacknowledged and active before returned-to-normal, higher priority first).
/// </summary>
public static class AlarmOrder
{
    /// <summary>Negative when <paramref name="a"/> (the alarm at project position <paramref name="aIndex"/>) comes first.</summary>
    public static int Compare(AlarmStatus a, int aIndex, AlarmStatus b, int bIndex)
    {
        ArgumentNullException.ThrowIfNull(a);
        ArgumentNullException.ThrowIfNull(b);
        var byState = StateRank(a.State).CompareTo(StateRank(b.State));
        if (byState != 0)
        {
            return byState;
        }

        var byClass = ClassRank(a.Definition.Class).CompareTo(ClassRank(b.Definition.Class));
        if (byClass != 0)
        {
            return byClass;
        }

        // Latest raise first; never raised last.
        var byTime = Nullable.Compare(b.RaisedAt, a.RaisedAt);
        return byTime != 0 ? byTime : aIndex.CompareTo(bIndex);
    }

    private static int StateRank(AlarmState state) => state switch
    {
        AlarmState.ActiveUnacknowledged => 0,
        AlarmState.ActiveAcknowledged => 1,
        AlarmState.ClearedUnacknowledged => 2,
        AlarmState.Cleared => 3,
    };

    private static int ClassRank(AlarmClass alarmClass) => alarmClass switch
    {
        AlarmClass.Fault => 0,
        AlarmClass.Warning => 1,
        AlarmClass.Information => 2,
    };
}
