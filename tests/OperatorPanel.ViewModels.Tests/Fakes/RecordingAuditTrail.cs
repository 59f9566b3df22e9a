using OperatorPanel.Core.Audit;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Keeps every audit entry in order; <c>onRecord</c> lets a test look at the world at the moment each is recorded.</summary>
internal sealed class RecordingAuditTrail(Action<AuditEntry>? onRecord = null) : IAuditTrail
{
    public List<AuditEntry> Entries { get; } = [];

    public ValueTask<string?> RecordAsync(AuditEntry entry, CancellationToken cancellationToken)
    {
        Entries.Add(entry);
        onRecord?.Invoke(entry);
        return ValueTask.FromResult<string?>(null);
    }
}
