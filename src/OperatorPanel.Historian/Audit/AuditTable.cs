using OperatorPanel.Core.Audit;
using OperatorPanel.Historian.Recording;

namespace OperatorPanel.Historian.Audit;

/// <summary>
/// The audit table's side of <see cref="IAuditTrail"/>: each entry is queued on the writer and the action goes on. It
/// never refuses (a historian is never the record that decides: AuditTrail.Combine puts the write journal first), never
/// blocks and never throws; a database that takes no writes is reported once by the writer.
/// </summary>
internal sealed class AuditTable(HistoryWriter writer) : IAuditTrail
{
    public ValueTask<string?> RecordAsync(AuditEntry entry, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(entry);
        writer.Enqueue(new AuditRow(entry));
        return ValueTask.FromResult<string?>(null);
    }
}
