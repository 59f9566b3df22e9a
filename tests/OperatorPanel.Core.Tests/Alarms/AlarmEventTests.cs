using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;

namespace OperatorPanel.Core.Tests.Alarms;

public sealed class AlarmEventTests
{
    [Theory]
    [InlineData(AlarmTransition.Raised, AlarmState.ActiveUnacknowledged, "raised", "active unacknowledged")]
    [InlineData(AlarmTransition.Acknowledged, AlarmState.ActiveAcknowledged, "acknowledged", "active acknowledged")]
    [InlineData(AlarmTransition.Cleared, AlarmState.Cleared, "cleared", "cleared")]
    public void Texts_TransitionAndState_ReadAsTheOperatorSaysThem(AlarmTransition transition, AlarmState state, string transitionText, string stateText)
    {
        var e = new AlarmEvent(DateTimeOffset.UnixEpoch, "Filler", new Station(2), PlcAddress.Parse("M2.2"), transition, state, AlarmClass.Warning, "Low product");

        (e.TransitionText, e.StateText).Should().Be((transitionText, stateText));
    }
}
