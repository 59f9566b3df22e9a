using OperatorPanel.Historian.Reading;

namespace OperatorPanel.ViewModels.Trends;

/// <summary>
/// What the Trends window draws, and all of it: the time window, one lane per tag (its own value axis, in the tag's
/// units), its known stretches as step lines and its gaps, and the cursor. The App renders it (ScottPlot into a bitmap);
/// everything that decides what is drawn is here, tested on Linux.
/// </summary>
public sealed record TrendPlot(DateTimeOffset From, DateTimeOffset To, IReadOnlyList<TrendLane> Lanes, DateTimeOffset? Cursor, bool IsLive)
{
    public static TrendPlot Empty { get; } = new(DateTimeOffset.UnixEpoch, DateTimeOffset.UnixEpoch.AddMinutes(10), [], null, true);
}

/// <summary>One tag's lane: the step segments where it was known, the gaps (not recorded, stale, bad), and its range.</summary>
/// <param name="Name">"Filler.TankLevel".</param>
/// <param name="Color">ARGB, from <see cref="TrendPalette"/>.</param>
/// <param name="Segments">Step lines; each point's value holds until the next point.</param>
/// <param name="Gaps">Stretches drawn as gaps, shaded by kind.</param>
/// <param name="Min">The lowest value shown (the axis's bottom before padding).</param>
/// <param name="Max">The highest value shown.</param>
/// <param name="IsBit">A 0/1 value: its axis shows 0 and 1 only.</param>
public sealed record TrendLane(string Name, uint Color, IReadOnlyList<TrendSegment> Segments, IReadOnlyList<TrendGap> Gaps, double Min, double Max, bool IsBit);
