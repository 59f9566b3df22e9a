using OperatorPanel.Core.Audit;

namespace OperatorPanel.Core.Tests.Audit;

/// <summary>An audit trail in memory: what was recorded, in order; can refuse, as a full disk would.</summary>
internal sealed class RecordingTrail : IAuditTrail
{
    private readonly Lock _lock = new();
    private readonly List<AuditEntry> _entries = [];

    /// <summary>When set, every entry is refused with this reason.</summary>
    public string? Refuse { get; set; }

    public IReadOnlyList<AuditEntry> Entries
    {
        get { lock (_lock) { return [.. _entries]; } }
    }

    public ValueTask<string?> RecordAsync(AuditEntry entry, CancellationToken cancellationToken)
    {
        if (Refuse is not null)
        {
            return ValueTask.FromResult<string?>(Refuse);
        }

        lock (_lock)
        {
            _entries.Add(entry);
        }

        return ValueTask.FromResult<string?>(null);
    }
}
