using OperatorPanel.Core.Polling;

namespace OperatorPanel.ViewModels.Values;

/// <summary>
/// Batches of changed values, as <see cref="PollingEngine.Subscribe"/> publishes them (on the polling thread). A view model
/// that outlives one connection subscribes here once; the shell feeds it from whichever engine is running
/// (see <see cref="ValueChangeRelay"/>).
/// </summary>
public interface IValueChangeSource
{
    /// <summary>Dispose the result to stop hearing about changes.</summary>
    IDisposable Subscribe(Action<IReadOnlyList<ValueChange>> onChanges);
}
