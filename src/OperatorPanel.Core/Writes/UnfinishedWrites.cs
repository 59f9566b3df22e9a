using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// Writes and STOPs cut short: their program ended (Ctrl+C, a kill, a crash, a power cut) after the intent was on
/// record and before the outcome. When a program opens a port it settles those of that port (the port is its own now,
/// PortLock) by reading each target back, never by writing again: the requested value is there (applied), the old one
/// (not applied), or neither or no answer (unknown); a STOP is settled by IDENTIFY (an answer means it runs). Each is
/// recorded as "resolved at start" and logged. Intents on a simulated line are settled as unknown: that PLC ended with
/// its program. When the port itself cannot be opened nothing is settled: a later start, with the port back, does it.
/// The read-back speaks the bus's own protocol: Freeport frames to the handler here, S7 read jobs on a PPI bus
/// (UnfinishedWrites.Ppi.cs), so no start sends one protocol's frames onto the other's bus.
/// </summary>
public static partial class UnfinishedWrites
{
    public const string Applied = "applied";
    public const string NotApplied = "not applied";
    public const string Unknown = "unknown";

    /// <summary>The settled writes and STOPs, oldest first; and a problem reading the journal, if any.</summary>
    public static Task<(IReadOnlyList<CutShortWrite> Resolved, string? Problem)> ResolveAsync(
        WriteJournal journal, IPlcLink link, string port, TimeProvider? time = null, ILogger? logger = null, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(link);
        return ResolveAsync(journal, port, (intent, ct) => ReadBackAsync(intent, link, ct), time, logger, cancellationToken);
    }

    private static async Task<(IReadOnlyList<CutShortWrite> Resolved, string? Problem)> ResolveAsync(
        WriteJournal journal, string port, Func<AuditEntry, CancellationToken, Task<Settlement>> readBack, TimeProvider? time, ILogger? logger, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(journal);
        ArgumentNullException.ThrowIfNull(port);
        var clock = time ?? TimeProvider.System;
        var log = logger ?? Logger.None;
        var (intents, problem) = journal.CutShort(p => IsSimulated(p) || SamePort(p, port));
        if (problem is not null)
        {
            log.Warning("{Problem:l}", problem);
        }

        var resolved = new List<CutShortWrite>();
        foreach (var intent in intents)
        {
            var settled = IsSimulated(intent.Port)
                ? new Settlement(Unknown, "it went to a simulated PLC, which ended with its program")
                : await readBack(intent, cancellationToken).ConfigureAwait(false);
            if (settled.PortGone)
            {
                log.Warning("{Action} {Entry:l} was cut short earlier and is not settled yet: {Reason:l}", intent.Action, intent.Describe(), settled.Detail);
                break; // the port is not there: the rest cannot be read either
            }

            var entry = intent.Then(AuditStep.ResolvedAtStart, clock.GetUtcNow(), settled.Outcome, settled.Detail);
            log.Warning(
                "{Action} {Entry:l} by {User:l} at {At:o} was cut short (its program ended before the outcome); resolved at start: {Outcome:l}: {Detail:l}",
                intent.Action, intent.Describe(), intent.User, intent.At, settled.Outcome, settled.Detail);
            if (await journal.RecordAsync(entry, cancellationToken).ConfigureAwait(false) is { } notKept)
            {
                log.Warning("{Problem:l}", notKept);
            }

            resolved.Add(new CutShortWrite(intent, entry));
        }

        return (resolved, problem);
    }

    /// <summary>A simulated line's port ("COM3 (demo)", Cli/Link/DemoLine and the app's demo).</summary>
    public static bool IsSimulated(string port) => port.EndsWith(" (demo)", StringComparison.Ordinal);

    private static bool SamePort(string a, string b) =>
        string.Equals(a, b, OperatingSystem.IsWindows() ? StringComparison.OrdinalIgnoreCase : StringComparison.Ordinal);

    private static async Task<Settlement> ReadBackAsync(AuditEntry intent, IPlcLink link, CancellationToken cancellationToken)
    {
        if (intent.Action == AuditAction.Stop)
        {
            return await IdentifyAsync(intent.Station, link, cancellationToken).ConfigureAwait(false);
        }

        if (!PlcAddress.TryParse(intent.Target, out var address, out _)
            || ProtocolAreaExtensions.FromMemoryArea(address.Area) is not { } area
            || !WriteLog.TryParse(address, intent.NewValue, out var requested))
        {
            return new Settlement(Unknown, $"the journal entry names no address or value this program reads ({intent.Target} := {intent.NewValue})");
        }

        var length = address.Bit is null ? address.Width.ByteCount() : 1;
        var reply = await link.ExchangeAsync(new ReadRequest(intent.Station, [new ReadItem(area, address.ByteOffset, length)]), cancellationToken).ConfigureAwait(false);
        if (reply.Failure is { } failure)
        {
            return failure.Kind == PlcErrorKind.PortUnavailable
                ? Settlement.PortUnavailable(failure.Message)
                : new Settlement(Unknown, $"the read-back failed: {failure.Message}");
        }

        if (reply.Response is not ReadResponse { Data.Length: var n } read || n != length)
        {
            return new Settlement(Unknown, $"the read-back got {(reply.Response is ErrorResponse refused ? ProtocolErrorText.Describe(refused.Error) : $"a {reply.Response?.Command} reply")}");
        }

        return Judge(intent, address, requested, read.Data.AsSpan());
    }

    /// <summary>Applied, not applied or unknown, from the bytes the target holds now (a bit's whole byte).</summary>
    private static Settlement Judge(AuditEntry intent, PlcAddress address, System.Collections.Immutable.ImmutableArray<byte> requested, ReadOnlySpan<byte> raw)
    {
        var now = ValueStore.Extract(address, raw);
        var nowText = WriteLog.Format(address, now);
        if (now.AsSpan().SequenceEqual(requested.AsSpan()))
        {
            return new Settlement(Applied, $"the PLC holds the requested {nowText}");
        }

        return WriteLog.TryParse(address, intent.OldValue, out var old) && now.AsSpan().SequenceEqual(old.AsSpan())
            ? new Settlement(NotApplied, $"the PLC still holds the old {nowText}")
            : new Settlement(Unknown, $"the PLC holds {nowText}, neither the old {intent.OldValue} nor the requested {intent.NewValue}: its program may have changed it since");
    }

    private static async Task<Settlement> IdentifyAsync(Station station, IPlcLink link, CancellationToken cancellationToken)
    {
        var reply = await link.ExchangeAsync(new IdentifyRequest(station), cancellationToken).ConfigureAwait(false);
        return reply.Failure switch
        {
            null => new Settlement(NotApplied, "the station answers IDENTIFY, so its program runs"),
            { Kind: PlcErrorKind.NoAnswer or PlcErrorKind.Timeout } => new Settlement(Unknown, "the station is silent: in STOP, at TERM or off the bus"),
            { Kind: PlcErrorKind.PortUnavailable } failure => Settlement.PortUnavailable(failure.Message),
            var failure => new Settlement(Unknown, $"IDENTIFY failed: {failure.Message}"),
        };
    }

    /// <summary>How a cut-short action was settled; <paramref name="PortGone"/>: not at all, the port could not be opened.</summary>
    private readonly record struct Settlement(string Outcome, string Detail, bool PortGone = false)
    {
        public static Settlement PortUnavailable(string message) => new(Unknown, message, PortGone: true);
    }
}
