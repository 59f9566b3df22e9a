namespace OperatorPanel.ViewModels.Services;

/// <summary>
/// Moves work onto the UI thread: the polling engine publishes changes on its own thread, bound properties must change
/// on the dispatcher's. Tests use an inline dispatcher.
/// </summary>
public interface IUiDispatcher
{
    void Post(Action action);
}
