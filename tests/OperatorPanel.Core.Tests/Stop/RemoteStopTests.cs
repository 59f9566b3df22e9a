using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Stop;
using OperatorPanel.Core.Tests.Polling;
using OperatorPanel.Core.Transport;
using Serilog.Events;

namespace OperatorPanel.Core.Tests.Stop;

/// <summary>
/// STOP as the panel sends it: only to a handler that has it (FEATURES bit 0), once, confirmed by the station's silence
/// afterwards; a lost reply settled by an IDENTIFY; every attempt logged as "RUN -> STOP by operator".
/// </summary>
public sealed class RemoteStopTests
{
    private static readonly Station Two = new(2);
    private readonly PollingLogSink _log = new();

    [Fact]
    public async Task Stop_HandlerWithStop_SendsStopOnceBetweenTwoIdentifiesAndReportsStopped()
    {
        var plc = new StoppablePlcLink(Two);

        var outcome = await Stop(plc);

        outcome.Should().Be(new StopOutcome.Stopped(Two));
        outcome.Text.Should().Be("station 2 stopped: the port speaks PPI until someone sets RUN");
        plc.Sent.Select(r => r.Command).Should().Equal(CommandCode.Identify, CommandCode.Stop, CommandCode.Identify);
        plc.InStop.Should().BeTrue();
        Logged().Should().Equal(
            (LogEventLevel.Information, "Station 2 RUN -> STOP by operator: sending STOP"),
            (LogEventLevel.Information, "Station 2 RUN -> STOP by operator: station 2 stopped: the port speaks PPI until someone sets RUN"));
    }

    [Fact]
    public async Task Stop_HandlerWithoutStop_SendsNoStopAndSaysHowToEnableIt()
    {
        var plc = new StoppablePlcLink(Two, features: HandlerIdentity.CopiesFeature);

        var outcome = await Stop(plc);

        outcome.Should().Be(new StopOutcome.NotInHandler(Two));
        outcome.Text.Should().Be(
            "station 2: its handler was generated without STOP (IDENTIFY FEATURES bit 0 is 0), nothing sent; set \"allowStop\": true for the "
            + "station in the project (or opanel generate --allow-stop), generate the PLC code again and download it");
        plc.Sent.Should().ContainSingle().Which.Should().BeOfType<IdentifyRequest>();
        Logged().Should().ContainSingle().Which.Level.Should().Be(LogEventLevel.Warning);
    }

    [Fact]
    public async Task Stop_AcknowledgedButStillAnswering_ReportsTheStopWasNotExecuted()
    {
        var plc = new StoppablePlcLink(Two) { Fate = StopFate.AcknowledgedButRunning };

        var outcome = await Stop(plc);

        outcome.Text.Should().Be("station 2 acknowledged STOP but still answers in Freeport: the STOP was not executed");
        outcome.IsStopped.Should().BeFalse();
        Logged()[^1].Should().Be((LogEventLevel.Warning, "Station 2 RUN -> STOP by operator: " + outcome.Text));
    }

    [Fact]
    public async Task Stop_ReplyLostAndStationSilent_StoppedReplyLostWithoutResending()
    {
        var plc = new StoppablePlcLink(Two) { Fate = StopFate.ExecutedReplyLost };

        var outcome = await Stop(plc);

        outcome.Should().Be(new StopOutcome.StoppedReplyLost(Two, "no reply within 120 ms"));
        outcome.Text.Should().Be("station 2 stopped (reply lost, station silent): no reply within 120 ms");
        plc.Sent.OfType<StopRequest>().Should().ContainSingle("a STOP the PLC may have acted on is never repeated");
        plc.Sent[^1].Should().BeOfType<IdentifyRequest>();
    }

    [Fact]
    public async Task Stop_RequestLostAndStationAnswers_NotStoppedWithoutResending()
    {
        var plc = new StoppablePlcLink(Two) { Fate = StopFate.RequestLost };

        var outcome = await Stop(plc);

        outcome.Should().Be(new StopOutcome.NotStopped(Two, "no reply within 120 ms"));
        outcome.Text.Should().Be("station 2 not stopped: the reply to STOP was lost (no reply within 120 ms) and the station still answers; send STOP again if still wanted");
        plc.Sent.OfType<StopRequest>().Should().ContainSingle();
        plc.InStop.Should().BeFalse();
    }

    [Fact]
    public async Task Stop_ReplyLostAndTheCheckFailsToo_Unknown()
    {
        var plc = new StoppablePlcLink(Two)
        {
            Fate = StopFate.ExecutedReplyLost,
            FailureAfterStop = new PlcCommunicationException(PlcErrorKind.PortUnavailable, Two, "station 2: serial port COM9: the device was removed"),
        };

        var outcome = await Stop(plc);

        outcome.Should().Be(new StopOutcome.Unknown(Two, "no reply within 120 ms", "station 2: serial port COM9: the device was removed"));
        outcome.Text.Should().EndWith("look at the CPU's RUN/STOP LED before sending STOP again");
    }

    [Fact]
    public async Task Stop_PortGoneBeforeTheFrameLeft_NotSent()
    {
        var plc = new StoppablePlcLink(Two) { Fate = StopFate.NeverSent };

        var outcome = await Stop(plc);

        outcome.Should().Be(new StopOutcome.NotSent(Two, "COM9 is gone"));
        plc.Sent.Should().ContainSingle().Which.Should().BeOfType<IdentifyRequest>();
    }

    [Fact]
    public async Task Stop_PlcRefuses_ReportsTheErrorAndDoesNotCheckAgain()
    {
        var plc = new StoppablePlcLink(Two) { Fate = StopFate.Refused };

        var outcome = await Stop(plc);

        outcome.Text.Should().Be("station 2 refused STOP: 85: unknown command (STOP in a handler generated without it, or a list command in a compact handler)");
        plc.Sent.Select(r => r.Command).Should().Equal(CommandCode.Identify, CommandCode.Stop);
    }

    [Fact]
    public async Task Stop_StationSilentBeforehand_SendsNoStop()
    {
        var plc = new StoppablePlcLink(Two) { InStop = true };

        var outcome = await Stop(plc);

        outcome.Should().BeOfType<StopOutcome.NotSent>().Which.Text.Should().Be(
            "station 2: STOP not sent: station 2 on fake: no valid reply to Identify after 2 attempts");
        plc.Sent.Should().ContainSingle().Which.Should().BeOfType<IdentifyRequest>();
    }

    [Fact]
    public async Task Stop_WithAudit_IntentOnRecordBeforeStopLeavesOutcomeAfter()
    {
        var trail = new Audit.RecordingTrail();
        var plc = new StoppablePlcLink(Two);
        var recordedWhenSent = -1;
        var audit = new Core.Audit.AuditContext(new SpyTrail(trail, () => recordedWhenSent = plc.Sent.OfType<StopRequest>().Count()), "COM9", "operator");

        await new RemoteStop(plc, _log.CreateLogger(), audit).StopAsync(Two);

        trail.Entries.Select(e => (e.Step, e.Action, e.OldValue, e.NewValue, e.Outcome)).Should().Equal(
            (Core.Audit.AuditStep.Intent, Core.Audit.AuditAction.Stop, "RUN", "STOP", null),
            (Core.Audit.AuditStep.Outcome, Core.Audit.AuditAction.Stop, "RUN", "STOP", "station 2 stopped: the port speaks PPI until someone sets RUN"));
        recordedWhenSent.Should().Be(0, "the intent was on record before the STOP left");
    }

    [Fact]
    public async Task Stop_IntentCannotBeRecorded_SendsNoStop()
    {
        var plc = new StoppablePlcLink(Two);
        var audit = new Core.Audit.AuditContext(new Audit.RecordingTrail { Refuse = "the disk is full" }, "COM9", "operator");

        var outcome = await new RemoteStop(plc, _log.CreateLogger(), audit).StopAsync(Two);

        outcome.Should().Be(new StopOutcome.NotSent(Two, "it could not be put on record (the disk is full)"));
        plc.Sent.OfType<StopRequest>().Should().BeEmpty();
    }

    /// <summary>Records into <paramref name="inner"/> and notes, at each record, how many STOPs had left.</summary>
    private sealed class SpyTrail(Audit.RecordingTrail inner, Action onRecord) : Core.Audit.IAuditTrail
    {
        private int _calls;

        public ValueTask<string?> RecordAsync(Core.Audit.AuditEntry entry, CancellationToken cancellationToken)
        {
            if (_calls++ == 0)
            {
                onRecord();
            }

            return inner.RecordAsync(entry, cancellationToken);
        }
    }

    private Task<StopOutcome> Stop(StoppablePlcLink plc) => new RemoteStop(plc, _log.CreateLogger()).StopAsync(Two);

    private List<(LogEventLevel Level, string Text)> Logged() =>
        [.. _log.Events.Where(e => e.MessageTemplate.Text.Contains("RUN -> STOP", StringComparison.Ordinal)).Select(e => (e.Level, e.RenderMessage()))];
}
