using OperatorPanel.Core.Alarms;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>No loudspeaker: a shell built without one (tests, a PC without sound) plays nothing.</summary>
public sealed class SilentAlarmSound : IAlarmSound
{
    public static SilentAlarmSound Instance { get; } = new();

    private SilentAlarmSound()
    {
    }

    public void Play(AlarmClass alarmClass)
    {
    }

    public void Stop()
    {
    }
}
