using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;
using Serilog;

namespace OperatorPanel.Core.Writes;

/// <summary>Settling cut-short writes on a PPI bus: the target is read back with an S7 read job, as PpiWriter confirms.</summary>
public static partial class UnfinishedWrites
{
    /// <summary>As <see cref="ResolveAsync(WriteJournal, IPlcLink, string, TimeProvider?, ILogger?, CancellationToken)"/>, over a PPI bus.</summary>
    public static Task<(IReadOnlyList<CutShortWrite> Resolved, string? Problem)> ResolveOverPpiAsync(
        WriteJournal journal, PpiLink link, string port, TimeProvider? time = null, ILogger? logger = null, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(link);
        return ResolveAsync(journal, port, (intent, ct) => ReadBackOverPpiAsync(intent, link, ct), time, logger, cancellationToken);
    }

    private static async Task<Settlement> ReadBackOverPpiAsync(AuditEntry intent, PpiLink link, CancellationToken cancellationToken)
    {
        if (intent.Action == AuditAction.Stop)
        {
            // The panel sends no STOP over PPI (Bus.StopAsync), and a CPU answers PPI in RUN and in STOP alike
            // (docs/ppi.md section 12), so no read here could tell whether an earlier STOP was done.
            return new Settlement(Unknown, "over PPI a CPU answers in RUN and in STOP alike, so whether the STOP was done cannot be read");
        }

        if (!PlcAddress.TryParse(intent.Target, out var address, out _)
            || !WriteLog.TryParse(address, intent.NewValue, out var requested)
            || !PpiAddressing.TryRange(address.Area, address.ByteOffset, address.Bit is null ? address.Width.ByteCount() : 1, out var item, out _))
        {
            return new Settlement(Unknown, $"the journal entry names no address or value this program reads over PPI ({intent.Target} := {intent.NewValue})");
        }

        ImmutableArray<S7ItemResult> results;
        try
        {
            await link.EnsureReadyAsync(intent.Station, cancellationToken).ConfigureAwait(false);
            results = await link.ReadAsync(intent.Station, [item], cancellationToken).ConfigureAwait(false);
        }
        catch (PlcCommunicationException failure)
        {
            return failure.Kind == PlcErrorKind.PortUnavailable
                ? Settlement.PortUnavailable(failure.Message)
                : new Settlement(Unknown, $"the read-back failed: {failure.Message}");
        }

        return results[0] is { Succeeded: true } result && result.Data.Length == item.DataLength
            ? Judge(intent, address, requested, result.Data.AsSpan())
            : new Settlement(Unknown, $"the read-back got {S7ReturnCodeText.Describe(results[0].Code)}");
    }
}
