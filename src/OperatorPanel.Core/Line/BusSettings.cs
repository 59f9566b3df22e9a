using OperatorPanel.Core.Audit;
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

    /// <summary>
    /// Where the bus's writes and STOPs go on record (the write journal, maybe with a historian: AuditTrail.Combine), with
    /// its port and the user: each intent before its frame leaves (not sent when it cannot be), each outcome before the
    /// caller hears it. Null records nothing (tests, tools that change no PLC).
    /// </summary>
    public IAuditTrail? Audit { get; init; }
}
