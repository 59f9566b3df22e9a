namespace OperatorPanel.Cli.Watch;

/// <summary>Link counters of one station (see <see cref="Core.Link.LinkStatistics"/>).</summary>
internal sealed record LinkView(long Requests, long Replies, long Retries, long Timeouts, double? RoundTripAverageMs);
