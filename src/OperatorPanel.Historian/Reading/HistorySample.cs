using OperatorPanel.Core.Polling;

namespace OperatorPanel.Historian.Reading;

/// <summary>One stored row of a value: from <see cref="At"/> the value was <see cref="Stored"/> (null: none) with <see cref="Quality"/>.</summary>
public readonly record struct HistorySample(DateTimeOffset At, long? Stored, ValueQuality Quality);
