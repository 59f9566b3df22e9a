namespace OperatorPanel.Core.Transport;

/// <summary>
/// Closing a port never holds the program: a USB serial adapter's driver can block in close for a long time or for
/// good (a classic on Windows with a pulled or wedged adapter), and a panel that hangs on exit is killed by operators,
/// losing what it had not written. The close runs on the thread pool; after <see cref="Limit"/> the caller goes on and
/// the close is left to finish (or not) in the background.
/// </summary>
internal static class BoundedClose
{
    /// <summary>The longest a close may hold its caller.</summary>
    public static readonly TimeSpan Limit = TimeSpan.FromSeconds(2);

    /// <summary>Runs <paramref name="close"/>; true when it ended within <paramref name="limit"/>, false when it was abandoned.</summary>
    public static async Task<bool> RunAsync(Func<Task> close, TimeSpan limit, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(close);
        ArgumentNullException.ThrowIfNull(time);
        var closing = Task.Run(close);
        using var stopTimer = new CancellationTokenSource();
        var timer = Task.Delay(limit, time, stopTimer.Token);
        var first = await Task.WhenAny(closing, timer).ConfigureAwait(false);
        if (first == closing)
        {
            await stopTimer.CancelAsync().ConfigureAwait(false);
            await closing.ConfigureAwait(false);
            return true;
        }

        // Abandoned: its failure, if it ever fails, has nobody left to tell.
        _ = closing.ContinueWith(t => _ = t.Exception, CancellationToken.None, TaskContinuationOptions.OnlyOnFaulted, TaskScheduler.Default);
        return false;
    }
}
