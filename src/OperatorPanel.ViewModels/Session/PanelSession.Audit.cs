using OperatorPanel.Core.Audit;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// Who works the panel, and where the project's history keeps writes and STOPs. The bus records each write and STOP
/// itself, intent before it is sent and outcome after (Core: the write job, Bus.StopAsync), in the write journal first,
/// which decides (a write it cannot record is not sent), then in <see cref="Audit"/> (AuditTrail.Combine), so the
/// history holds the journal's entries.
/// </summary>
public sealed partial class PanelSession
{
    /// <summary>Where each write and STOP is also recorded (the project's history, set by ProjectHistory); none without a history.</summary>
    public IAuditTrail Audit { get; set; } = AuditTrail.None;

    /// <summary>Who works the panel, as the alarm journal records an acknowledgement: DOMAIN\user on Windows.</summary>
    public string User { get; init; } = AuditUser.Current;

    /// <summary>The session's <see cref="Audit"/> as it is when an entry comes: the history follows the open project, the line's options are fixed.</summary>
    private sealed class HistoryTrail(PanelSession session) : IAuditTrail
    {
        public ValueTask<string?> RecordAsync(AuditEntry entry, CancellationToken cancellationToken) => session.Audit.RecordAsync(entry, cancellationToken);
    }
}
