namespace OperatorPanel.Core.Link;

/// <summary>
/// A snapshot of one station's link counters, as the diagnostics view and `opanel` show them. <see cref="Requests"/>
/// counts attempts that have ended (answered, timed out, corrupt, or cut off by the port), so a snapshot never shows the
/// frame in flight as a request without its outcome.
/// </summary>
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

    /// <summary>
    /// Error replies whose REQCHECK was not the request's: the PLC refused a corrupted copy, so the link retried once
    /// (docs/protocol-v2.md, REQCHECK). Counted apart from <see cref="NegativeReplies"/>, which are real refusals.
    /// </summary>
    public long CorruptedRefusals { get; init; }
}
