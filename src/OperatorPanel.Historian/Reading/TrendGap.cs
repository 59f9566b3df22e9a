namespace OperatorPanel.Historian.Reading;

/// <summary>A stretch of a trend drawn as a gap: nothing trustworthy is known of the value then.</summary>
public sealed record TrendGap(DateTimeOffset From, DateTimeOffset To, TrendGapKind Kind);

/// <summary>Why a trend has a gap.</summary>
public enum TrendGapKind
{
    /// <summary>The recorder did not run (panel closed, line not watched).</summary>
    NotRecorded,

    /// <summary>The station stopped answering: the last value read is all there is.</summary>
    Stale,

    /// <summary>Never read, or the station refused the read.</summary>
    Bad,
}

/// <summary>What a trend's cursor reads: the value, or why there is none.</summary>
public sealed record TrendReading(double? Value, TrendGapKind? Gap);
