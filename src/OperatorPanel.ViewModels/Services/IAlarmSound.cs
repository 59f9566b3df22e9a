using OperatorPanel.Core.Alarms;

namespace OperatorPanel.ViewModels.Services;

/// <summary>The panel's loudspeaker: one alarm tone per class (AlarmTone), played once per call; the App plays it through Windows.</summary>
public interface IAlarmSound
{
    void Play(AlarmClass alarmClass);

    /// <summary>Cuts a tone that is still playing (the operator silenced or acknowledged).</summary>
    void Stop();
}
