using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Stop;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// Writes and STOPs on record in <see cref="Audit"/> (the project's history), intent before the job is queued on the bus
/// and outcome after, as Core/Audit's <see cref="AuditEntry"/> in the words of issue 24's Core/Writes/WriteAudit. The
/// bus does not record them on this branch; once it does (issue 24: ProjectLineOptions.Audit, the write journal first,
/// AuditTrail.Combine), this file goes and the history's trail is handed to the line instead.
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
        var context = ContextFor(request.Station);
        var intent = new AuditEntry(
            Guid.NewGuid(), AuditStep.Intent, AuditAction.Write, _time.GetUtcNow(), context.User, context.Port, request.Station, request.Address.ToString(),
            request.Symbol ?? SymbolOf(request.Station, request.Address), ValueText(request.Address, old.Raw), ValueText(request.Address, request.Value));
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

        var (words, detail) = outcome switch
        {
            WriteOutcome.Confirmed => ("confirmed", null),
            WriteOutcome.ReadBackMismatch m => ("read back differently", $"read back {ValueText(request.Address, m.ReadBack)}"),
            WriteOutcome.ConfirmedByReadBack c => ("confirmed (reply lost, read back)", c.Cause),
            WriteOutcome.NotApplied n => ("not applied", $"{n.Cause}; read back {ValueText(request.Address, n.ReadBack)}"),
            WriteOutcome.Unknown u => ("unknown", $"{u.Cause}; {u.Detail}"),
            WriteOutcome.Failed f => ("failed, nothing written", f.Reason),
            _ => throw new ArgumentOutOfRangeException(nameof(request), outcome, null),
        };
        await Audit.RecordAsync(intent.Then(AuditStep.Outcome, _time.GetUtcNow(), words, detail), CancellationToken.None);
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

    /// <summary>A value as the write log prints it (Core's WriteLog.Format): "unknown", "0"/"1", "16#002A".</summary>
    private static string ValueText(PlcAddress address, ImmutableArray<byte> raw) =>
        raw.IsDefaultOrEmpty ? "unknown"
        : address.Width == AccessWidth.Bit ? (raw[0] != 0 ? "1" : "0")
        : "16#" + Convert.ToHexString(raw.AsSpan());

    /// <summary>The project's name for the address (a tag or an I/O symbol of the station); null when it has none.</summary>
    private string? SymbolOf(Station station, PlcAddress address) =>
        Project.Stations.FirstOrDefault(s => s.Address == station) is { } project
            ? project.Tags.FirstOrDefault(t => t.Address == address)?.Symbol ?? project.Outputs.Concat(project.Inputs).FirstOrDefault(s => s.Address == address)?.Symbol
            : null;

    private AuditContext ContextFor(Station station) =>
        new(Audit, Project.Stations.FirstOrDefault(s => s.Address == station)?.Link.PortName ?? string.Empty, User);
}
