using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Line;

/// <summary>How a <see cref="ProjectLine"/> sets up its buses and where it hands values to subscribers.</summary>
public sealed record ProjectLineOptions
{
    /// <summary>Timing and retry rules of each bus's link; the medium's defaults unless a caller allows longer PLC scans.</summary>
    public Func<SerialSettings, LinkOptions> LinkOptionsFor { get; init; } = serial => V3LinkOptions.For(serial);

    /// <summary>Timing and repeats of a PPI bus's masters; the master's defaults at the bus's baud unless a caller allows more.</summary>
    public Func<SerialSettings, PpiMasterOptions> PpiOptionsFor { get; init; } = serial => PpiMasterOptions.ForBaud(serial.BaudRate);

    /// <summary>
    /// Runs one batch of subscriber calls. The polling loops run on their own threads: the panel passes its UI
    /// dispatcher here, so every <see cref="ILineValues.Subscribe"/> callback runs on the UI thread. Default: at once.
    /// </summary>
    public Action<Action> Deliver { get; init; } = work => work();

    /// <summary>Stored lists (default) or plain READs only (PollingOptions.UseReadLists).</summary>
    public bool UseReadLists { get; init; } = true;

    /// <summary>
    /// The write journal: every write and STOP goes on record there (unless <see cref="Audit"/> names another trail), and
    /// on connecting, the writes its port's earlier programs left cut short are settled (Writes/UnfinishedWrites).
    /// </summary>
    public WriteJournal? Journal { get; init; }

    /// <summary>Where writes and STOPs go on record when not (only) the journal, e.g. the journal and a historian (AuditTrail.Combine).</summary>
    public IAuditTrail? Audit { get; init; }
}
