using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Core.Line;

/// <summary>
/// The one way values leave a line: <see cref="Subscribe"/> for value changes, <see cref="TryGetValue"/> for the value
/// now. <see cref="ProjectLine"/> implements it; a row of the Inputs, Outputs or Memory window subscribes to its own
/// address, so a change goes straight to the one row that shows it.
/// </summary>
public interface ILineValues
{
    /// <summary>
    /// Calls <paramref name="onValue"/> at once with the address's value now, then with every change of value or quality
    /// (a poll cycle, a write's read-back, connect, disconnect, a new watch list), where the line delivers them (the UI
    /// thread in the panel). Dispose the result to stop.
    /// </summary>
    IDisposable Subscribe(Station station, PlcAddress address, Action<PolledValue> onValue);

    /// <summary>The latest value of a watched address; false (and a not-read value) when not connected or not watched.</summary>
    bool TryGetValue(Station station, PlcAddress address, out PolledValue value);
}
