using OperatorPanel.Core.Link;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// What the socat run measured: the link's per-exchange statistics (request written to reply decoded) and the duration
/// of each full refresh (all READ frames of the plan plus the link's inter-frame gaps).
/// </summary>
internal sealed record MeasuredRoundTrip(
    string Settings,
    int Cycles,
    int FramesPerRefresh,
    int FramesFailed,
    LinkStatistics Exchanges,
    double RefreshMinMs,
    double RefreshAverageMs,
    double RefreshMaxMs);
