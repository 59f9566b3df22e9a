namespace OperatorPanel.Core.Polling;

/// <summary>How the polling engine reads stored lists (docs/protocol.md, READ CHANGES, "PC rules").</summary>
public sealed record PollingOptions
{
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
}
