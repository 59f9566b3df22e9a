using OperatorPanel.Core.Audit;
using OperatorPanel.Historian.Recording;

namespace OperatorPanel.Historian.Audit;

/// <summary>The audit table's side of <see cref="IAuditTrail"/>: each entry is queued on the writer; never blocks, never throws.</summary>
internal sealed class AuditTrail(HistoryWriter writer) : IAuditTrail
{
    public void Record(AuditEntry entry)
    {
        ArgumentNullException.ThrowIfNull(entry);
        writer.Enqueue(new AuditRow(entry));
    }
}
