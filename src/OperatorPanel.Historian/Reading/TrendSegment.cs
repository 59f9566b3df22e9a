namespace OperatorPanel.Historian.Reading;

/// <summary>A stretch of a trend where the value was known: points of a step line, each value held until the next point.</summary>
public sealed record TrendSegment(IReadOnlyList<TrendPoint> Points);

/// <summary>A trend's value (in the tag's units) from <see cref="At"/> on.</summary>
public readonly record struct TrendPoint(DateTimeOffset At, double Value);
