namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>A hang fails the test after a real-time bound instead of stalling the run; nothing here waits on purpose.</summary>
internal static class TaskGuard
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(10);

    public static Task<T> Guarded<T>(this Task<T> task) => task.WaitAsync(Bound);

    public static Task Guarded(this Task task) => task.WaitAsync(Bound);
}
