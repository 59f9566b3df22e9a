using OperatorPanel.Core.Alarms;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>A loudspeaker that writes down what it played: "fault", "warning", "information", "stop".</summary>
internal sealed class FakeAlarmSound : IAlarmSound
{
    public List<string> Played { get; } = [];

    public void Play(AlarmClass alarmClass) => Played.Add(alarmClass.ToString().ToLowerInvariant());

    public void Stop() => Played.Add("stop");
}
