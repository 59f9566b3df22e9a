using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Alarms;

/// <summary>One line of the alarm history: a transition with its time and the alarm's text and class at that time.</summary>
/// <param name="At">When the panel saw the transition (UTC, from the injected TimeProvider).</param>
/// <param name="StationName">The project's name of the station, e.g. "Filler".</param>
/// <param name="Station">The station's bus address.</param>
/// <param name="Flag">The alarm's flag bit.</param>
/// <param name="Transition">Raised, acknowledged or cleared.</param>
/// <param name="State">The alarm's state after the transition.</param>
/// <param name="Class">The alarm class from the definition.</param>
/// <param name="Text">The alarm text from the definition.</param>
public sealed record AlarmEvent(
    DateTimeOffset At,
    string StationName,
    Station Station,
    PlcAddress Flag,
    AlarmTransition Transition,
    AlarmState State,
    AlarmClass Class,
    string Text)
{
    /// <summary>The transition as the history window and the CSV say it: "raised", "acknowledged", "cleared".</summary>
    public string TransitionText => AlarmCsv.Words(Transition.ToString());

    /// <summary>The state after it as the operator reads it: "active unacknowledged", not "ActiveUnacknowledged".</summary>
    public string StateText => AlarmCsv.Words(State.ToString());
}
