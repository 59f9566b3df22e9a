namespace OperatorPanel.Core.Link;

/// <summary>A snapshot of one station's link counters, as the diagnostics view and `opanel` show them.</summary>
public sealed record LinkStatistics(
    long Requests,
    long Replies,
    long Retries,
    long Timeouts,
    long CorruptFrames,
    long NegativeReplies,
    TimeSpan? RoundTripMin,
    TimeSpan? RoundTripAverage,
    TimeSpan? RoundTripMax)
{
    public static LinkStatistics Empty { get; } = new(0, 0, 0, 0, 0, 0, null, null, null);
}
