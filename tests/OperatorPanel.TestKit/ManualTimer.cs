namespace OperatorPanel.TestKit;

/// <summary>A timer of <see cref="ManualTimeProvider"/>: due times in the provider's clock, fired by Advance.</summary>
internal sealed class ManualTimer(ManualTimeProvider owner, TimerCallback callback, object? state) : ITimer
{
    /// <summary>Guarded by the owner's lock; null when not scheduled.</summary>
    internal DateTimeOffset? DueAt { get; set; }

    internal TimeSpan Period { get; set; }

    public bool Change(TimeSpan dueTime, TimeSpan period)
    {
        owner.Schedule(this, dueTime, period);
        return true;
    }

    public void Dispose() => owner.Remove(this);

    public ValueTask DisposeAsync()
    {
        Dispose();
        return ValueTask.CompletedTask;
    }

    internal void Fire() => callback(state);
}
