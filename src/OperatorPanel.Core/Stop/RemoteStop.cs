using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.Core.Stop;

/// <summary>
/// Puts a station into STOP (docs/protocol-v2.md, "07 STOP"), the way the CLI and the panel both do it: IDENTIFY first
/// (nothing is sent unless FEATURES bit 0 says the handler carries STOP), then 07 once, never repeated, then IDENTIFY
/// again. A CPU in STOP speaks PPI and answers no Freeport frame, so silence after STOP is the confirmation and an
/// answer means it still runs; a lost reply is settled the same way, as a lost write reply is settled by reading back.
/// Every attempt is logged like a write: "Station 2 RUN -> STOP by operator" with its outcome; with an audit trail its
/// intent is on record before 07 leaves (not sent when it cannot be) and its outcome after, as a write's.
/// </summary>
public sealed class RemoteStop(IPlcLink link, ILogger? logger = null, AuditContext? audit = null, TimeProvider? time = null)
{
    private readonly IPlcLink _link = link ?? throw new ArgumentNullException(nameof(link));
    private readonly ILogger _log = (logger ?? Logger.None).ForContext<RemoteStop>();
    private readonly TimeProvider _time = time ?? TimeProvider.System;

    public Task<StopOutcome> StopAsync(Station station, CancellationToken cancellationToken = default) => StopAsync(station, null, cancellationToken);

    /// <summary>
    /// As <see cref="StopAsync(Station, CancellationToken)"/>, and nothing is sent when the IDENTIFY does not fit
    /// <paramref name="expectedCpu"/> (the project's CPU, or --cpu): a STOP meant for one CPU must not stop another.
    /// </summary>
    public async Task<StopOutcome> StopAsync(Station station, CpuProfile? expectedCpu, CancellationToken cancellationToken = default)
    {
        var outcome = await CheckAsync(station, expectedCpu, cancellationToken).ConfigureAwait(false);
        if (outcome is null)
        {
            var intent = audit is null ? null : new AuditEntry(
                Guid.NewGuid(), AuditStep.Intent, AuditAction.Stop, _time.GetUtcNow(), audit.User, audit.Port, station, null, null, "RUN", "STOP");
            if (intent is not null && await audit!.Trail.RecordAsync(intent, CancellationToken.None).ConfigureAwait(false) is { } notKept)
            {
                outcome = new StopOutcome.NotSent(station, $"it could not be put on record ({notKept})");
            }
            else
            {
                _log.Information("Station {Station} RUN -> STOP by operator: sending STOP", station.Address);
                var sent = await _link.ExchangeAsync(new StopRequest(station), cancellationToken).ConfigureAwait(false);
                outcome = await JudgeAsync(station, sent, cancellationToken).ConfigureAwait(false);
                await RecordOutcomeAsync(intent, outcome).ConfigureAwait(false);
            }
        }

        if (outcome.IsStopped)
        {
            _log.Information("Station {Station} RUN -> STOP by operator: {Outcome:l}", station.Address, outcome.Text);
        }
        else
        {
            _log.Warning("Station {Station} RUN -> STOP by operator: {Outcome:l}", station.Address, outcome.Text);
        }

        return outcome;
    }

    private async Task RecordOutcomeAsync(AuditEntry? intent, StopOutcome outcome)
    {
        if (intent is not null && audit is not null
            && await audit.Trail.RecordAsync(intent.Then(AuditStep.Outcome, _time.GetUtcNow(), outcome.Text, null), CancellationToken.None).ConfigureAwait(false) is { } notKept)
        {
            _log.Warning("Station {Station} STOP: its outcome could not be put on record: {Reason:l}", intent.Station.Address, notKept);
        }
    }

    /// <summary>Null when the station answers IDENTIFY and its handler carries STOP; else why nothing may be sent.</summary>
    private async Task<StopOutcome?> CheckAsync(Station station, CpuProfile? expectedCpu, CancellationToken cancellationToken)
    {
        var reply = await _link.ExchangeAsync(new IdentifyRequest(station), cancellationToken).ConfigureAwait(false);
        return reply.Response switch
        {
            null => new StopOutcome.NotSent(station, reply.Failure!.Message),
            IdentifyResponse identity when expectedCpu is not null && IdentifyCheck.Mismatch(identity, expectedCpu) is { } mismatch =>
                new StopOutcome.WrongCpu(station, expectedCpu.Name, mismatch),
            IdentifyResponse { StopEnabled: true } => null,
            IdentifyResponse => new StopOutcome.NotInHandler(station),
            ErrorResponse refused => new StopOutcome.NotSent(station, $"IDENTIFY refused: {ProtocolErrorText.Describe(refused.Error)}"),
            var other => new StopOutcome.NotSent(station, $"IDENTIFY answered with a {other.Command} reply"),
        };
    }

    private async Task<StopOutcome> JudgeAsync(Station station, LinkReply sent, CancellationToken cancellationToken)
    {
        switch (sent)
        {
            case LinkReply.Answered { Response: StopResponse }:
                var check = await CheckSilenceAsync(station, cancellationToken).ConfigureAwait(false);
                return check.Answers switch
                {
                    true => new StopOutcome.NotExecuted(station),
                    false => new StopOutcome.Stopped(station),
                    null => new StopOutcome.Unknown(station, "the STOP reply came but the IDENTIFY after it failed", check.Failure),
                };
            case LinkReply.Answered { Response: ErrorResponse refused }:
                return new StopOutcome.Refused(station, ProtocolErrorText.Describe(refused.Error));
            case LinkReply.Answered answered:
                return await SettleLostAsync(station, $"a {answered.Response.Command} reply came instead", cancellationToken).ConfigureAwait(false);
            case LinkReply.Failed { Sent: false } notSent:
                return new StopOutcome.NotSent(station, notSent.Failure.Message);
            case LinkReply.Failed lost:
                return await SettleLostAsync(station, lost.Failure.Message, cancellationToken).ConfigureAwait(false);
            default:
                throw new ArgumentOutOfRangeException(nameof(sent), sent, null);
        }
    }

    private async Task<StopOutcome> SettleLostAsync(Station station, string cause, CancellationToken cancellationToken)
    {
        var check = await CheckSilenceAsync(station, cancellationToken).ConfigureAwait(false);
        return check.Answers switch
        {
            true => new StopOutcome.NotStopped(station, cause),
            false => new StopOutcome.StoppedReplyLost(station, cause),
            null => new StopOutcome.Unknown(station, cause, check.Failure),
        };
    }

    /// <summary>
    /// One IDENTIFY, with the link's retries so that one lost reply is not taken for a STOP. Answers is true when
    /// anything answered it, false when the station stayed silent, null when the link failed otherwise (the port gone,
    /// garbled replies), with the failure.
    /// </summary>
    private async Task<SilenceCheck> CheckSilenceAsync(Station station, CancellationToken cancellationToken)
    {
        if ((await _link.ExchangeAsync(new IdentifyRequest(station), cancellationToken).ConfigureAwait(false)).Failure is not { } failure)
        {
            return new SilenceCheck(true, string.Empty);
        }

        bool? answers = failure.Kind switch
        {
            PlcErrorKind.NoAnswer or PlcErrorKind.Timeout => false,
            PlcErrorKind.HandlerOutdated or PlcErrorKind.NegativeReply => true,
            PlcErrorKind.PortUnavailable or PlcErrorKind.FrameCorrupt or PlcErrorKind.AnotherMaster => null,
        };
        return new SilenceCheck(answers, failure.Message);
    }

    private readonly record struct SilenceCheck(bool? Answers, string Failure);
}
