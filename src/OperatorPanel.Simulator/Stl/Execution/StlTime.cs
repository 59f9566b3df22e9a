namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// The simulated clock of one CPU, in ns since power-up: no real time passes. <see cref="Busy"/> is the part of it
/// spent executing (instructions, interrupt entry and exit, scan housekeeping, the host's user program time).
/// </summary>
internal sealed class StlTime
{
    public const long Millisecond = 1_000_000;

    public long Now { get; set; }

    public long Busy { get; set; }

    /// <summary>Time spent executing: the clock and the busy time both move on.</summary>
    public void Spend(long nanoseconds)
    {
        Now += nanoseconds;
        Busy += nanoseconds;
    }

    public static TimeSpan ToTimeSpan(long nanoseconds) => TimeSpan.FromTicks(nanoseconds / 100);

    public static long FromTimeSpan(TimeSpan time) => time.Ticks * 100;
}
