using System.Collections.Concurrent;

namespace OperatorPanel.Core.Transport;

/// <summary>
/// One dedicated thread running blocking port calls in order, so a read waiting out its timeout never holds a
/// thread-pool thread (on Windows the serial stream's async reads ignore ReadTimeout and cancellation, so reads block).
/// </summary>
internal sealed class SerialIoLane
{
    private readonly BlockingCollection<Action> _work = [];
    private readonly TaskCompletionSource _stopped = new(TaskCreationOptions.RunContinuationsAsynchronously);

    public SerialIoLane(string name)
    {
        var thread = new Thread(Run) { IsBackground = true, Name = name };
        thread.Start();
    }

    public Task<T> Run<T>(Func<T> operation)
    {
        var completion = new TaskCompletionSource<T>(TaskCreationOptions.RunContinuationsAsynchronously);
        _work.Add(() => Execute(operation, completion));
        return completion.Task;
    }

    /// <summary>Lets queued work finish, then ends the thread.</summary>
    public Task StopAsync()
    {
        _work.CompleteAdding();
        return _stopped.Task;
    }

    private static void Execute<T>(Func<T> operation, TaskCompletionSource<T> completion)
    {
        try
        {
            completion.SetResult(operation());
        }
        catch (OperationCanceledException canceled)
        {
            completion.SetCanceled(canceled.CancellationToken);
        }
#pragma warning disable CA1031 // every failure is handed to the awaiting caller, none is swallowed
        catch (Exception failure)
#pragma warning restore CA1031
        {
            completion.SetException(failure);
        }
    }

    private void Run()
    {
        foreach (var item in _work.GetConsumingEnumerable())
        {
            item();
        }

        _work.Dispose();
        _stopped.SetResult();
    }
}
