using OperatorPanel.Core.Polling;
namespace OperatorPanel.Core.Projects;

/// <summary>How a project refreshes its stations.</summary>
/// <param name="Mode">Continuous or on demand ("triggered" in the file, as in seed 000 §7).</param>
/// <param name="MinimumPeriod">Shortest time between the starts of two poll cycles in continuous mode, 0-60 s.</param>
public sealed record RefreshSettings(RefreshMode Mode, TimeSpan MinimumPeriod)
{
    /// <summary>Upper bound of <see cref="MinimumPeriod"/>; slower than once a minute is no longer monitoring.</summary>
    public static readonly TimeSpan MaxMinimumPeriod = TimeSpan.FromMilliseconds(60_000);

    /// <summary>Continuous, at most ten cycles a second.</summary>
    public static RefreshSettings Default { get; } = new(RefreshMode.Continuous, TimeSpan.FromMilliseconds(100));
}
