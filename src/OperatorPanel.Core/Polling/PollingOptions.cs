namespace OperatorPanel.Core.Polling;

/// <summary>How the polling engine reads stored lists (docs/protocol-v2.md, READ CHANGES, "PC rules") and how often it tries an offline station.</summary>
public sealed record PollingOptions
{
    /// <summary>
    /// Poll the plan's lists as stored lists (default: DEFINE LIST once, then READ CHANGES or READ LIST), or every frame
    /// with plain READ, one exchange per frame and cycle (what a one-off read or a triggered watch wants: registering the
    /// lists would only add exchanges).
    /// </summary>
    public bool UseReadLists { get; init; } = true;

    /// <summary>
    /// Poll stored lists with READ CHANGES (default), so an unchanged byte costs nothing; false for READ LIST, whose
    /// reply always carries the whole list.
    /// </summary>
    public bool UseReadChanges { get; init; } = true;

    /// <summary>
    /// READ CHANGES asks FULL at least this often per list: a guard against drift between the PC's data and the PLC's
    /// copy (protocol rule 3: at least every 10 s).
    /// </summary>
    public TimeSpan FullReadInterval { get; init; } = TimeSpan.FromSeconds(10);

    /// <summary>
    /// In continuous refresh, a station that stayed silent (offline, or stopped by the panel) in a cycle in which another
    /// station of the bus answered is tried once per this interval instead of every cycle: each try costs the bus its
    /// reply time-outs, which would slow every other station's refresh. Silence while no station of the bus answers
    /// never rests (nobody waits, and a returning cable shows at once). In triggered refresh every refresh tries every
    /// station.
    /// </summary>
    public TimeSpan OfflineRetryInterval { get; init; } = TimeSpan.FromSeconds(5);
}
