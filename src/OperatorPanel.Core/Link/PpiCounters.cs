namespace OperatorPanel.Core.Link;

/// <summary>A PPI bus's counters for Diagnostics: jobs answered, polls answered "no data yet" (16#E5), frames sent again.</summary>
public sealed record PpiCounters(int Jobs, int EmptyPolls, int Repeats)
{
    public static PpiCounters None { get; } = new(0, 0, 0);
}
