namespace OperatorPanel.Core.Polling;

/// <summary>
/// Wakes the polling loop when work arrives (a job of the bus's queue, a refresh request, a mode change). Take <see cref="Current"/>
/// before looking for work, then await it: a <see cref="Set"/> in between is never lost.
/// </summary>
internal sealed class WakeSignal
{
    private readonly Lock _lock = new();
    private TaskCompletionSource _current = New();

    public Task Current
    {
        get
        {
            lock (_lock)
            {
                return _current.Task;
            }
        }
    }

    public void Set()
    {
        TaskCompletionSource fired;
        lock (_lock)
        {
            fired = _current;
            _current = New();
        }

        fired.TrySetResult();
    }

    private static TaskCompletionSource New() => new(TaskCreationOptions.RunContinuationsAsynchronously);
}
