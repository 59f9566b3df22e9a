using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Stop;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// Writes and STOPs on record in <see cref="Audit"/> (the project's history), intent before the job is queued on the bus
/// and outcome after, as Core/Audit's <see cref="AuditEntry"/> (WriteAudit's words). The bus does not record them on
/// this branch; once it does (issue 24: ProjectLineOptions.Audit, the write journal first, AuditTrail.Combine), this
/// file goes and the history's trail is handed to the line instead.
/// </summary>
public sealed partial class PanelSession
{
    /// <summary>Where each write and STOP is recorded (the project's history, set by ProjectHistory); none without a history.</summary>
    public IAuditTrail Audit { get; set; } = AuditTrail.None;

    /// <summary>Who works the panel, as the audit and the alarm journal record it: DOMAIN\user on Windows.</summary>
    public string User { get; init; } = AuditUser.Current;

    private async Task<WriteOutcome> RecordedAsync(WriteRequest request, CancellationToken cancellationToken)
    {
        _line.TryGetValue(request.Station, request.Address, out var old);
        var intent = WriteAudit.Intent(request, OldValueText(request.Address, old.Raw), ContextFor(request.Station), _time.GetUtcNow());
        if (await Audit.RecordAsync(intent, cancellationToken) is { } refused)
        {
            return new WriteOutcome.Failed($"{request.Address}: nothing written, the write could not be put on record ({refused})", WriteFailureKind.InvalidRequest);
        }

        WriteOutcome outcome;
        try
        {
            outcome = await _line.WriteAsync(request, cancellationToken);
        }
        catch (OperationCanceledException)
        {
            // The bus withdraws a cancelled write only while it is queued (BusJob): nothing was sent.
            await Audit.RecordAsync(intent.Then(AuditStep.Outcome, _time.GetUtcNow(), "withdrawn", "cancelled before it was sent; nothing written"), CancellationToken.None);
            throw;
        }

        await Audit.RecordAsync(WriteAudit.Outcome(intent, request, outcome, _time.GetUtcNow()), CancellationToken.None);
        return outcome;
    }

    private async Task<StopOutcome> StopRecordedAsync(Station station, CancellationToken cancellationToken)
    {
        var context = ContextFor(station);
        var intent = new AuditEntry(Guid.NewGuid(), AuditStep.Intent, AuditAction.Stop, _time.GetUtcNow(), context.User, context.Port, station, null, null, "RUN", "STOP");
        if (await Audit.RecordAsync(intent, cancellationToken) is { } refused)
        {
            return new StopOutcome.NotSent(station, $"STOP could not be put on record ({refused}), nothing sent");
        }

        var outcome = await _line.StopAsync(station, cancellationToken);
        await Audit.RecordAsync(intent.Then(AuditStep.Outcome, _time.GetUtcNow(), outcome.Text, null), CancellationToken.None);
        return outcome;
    }

    /// <summary>The last polled value as the write log prints it (Core's WriteLog.Format): "unknown", "0"/"1", "16#002A".</summary>
    private static string OldValueText(PlcAddress address, ImmutableArray<byte> raw) =>
        raw.IsDefaultOrEmpty ? "unknown"
        : address.Width == AccessWidth.Bit ? (raw[0] != 0 ? "1" : "0")
        : "16#" + Convert.ToHexString(raw.AsSpan());

    private AuditContext ContextFor(Station station) =>
        new(Audit, Project.Stations.FirstOrDefault(s => s.Address == station)?.Link.PortName ?? string.Empty, User);
}
