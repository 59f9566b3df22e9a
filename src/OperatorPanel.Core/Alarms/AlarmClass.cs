namespace OperatorPanel.Core.Alarms;

/// <summary>How serious an alarm is; the alarm window sorts and colours by it.</summary>
public enum AlarmClass
{
    /// <summary>The line stopped or must stop: e-stop, jam, drive fault.</summary>
    Fault,

    /// <summary>The line runs but needs attention soon: low level, door open.</summary>
    Warning,

    /// <summary>A notice with no action needed: batch complete.</summary>
    Information,
}
