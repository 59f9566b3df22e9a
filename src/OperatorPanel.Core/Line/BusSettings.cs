using OperatorPanel.Core.Polling;

namespace OperatorPanel.Core.Line;

/// <summary>How a <see cref="Bus"/> polls: its refresh mode to start with, the minimum period in continuous mode, and the polling options.</summary>
public sealed record BusSettings
{
    /// <summary>On demand with plain READs: a one-off read or write, a connection test.</summary>
    public static BusSettings OnDemand { get; } = new() { Mode = RefreshMode.OnDemand, Polling = new PollingOptions { UseReadLists = false } };

    public RefreshMode Mode { get; init; } = RefreshMode.Continuous;

    /// <summary>In continuous mode a cycle never starts sooner than this after the previous one started (the project's refresh setting).</summary>
    public TimeSpan MinimumPeriod { get; init; } = TimeSpan.FromMilliseconds(100);

    public PollingOptions Polling { get; init; } = new();
}
