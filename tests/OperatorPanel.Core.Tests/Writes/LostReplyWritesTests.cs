using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Tests.Polling;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using Serilog.Events;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Writes;

/// <summary>A write whose reply is lost is settled by reading the target back, never by sending it again.</summary>
public sealed class LostReplyWritesTests
{
    private readonly PollingTestClock _clock = new();
    private readonly PollingLogSink _log = new();
    private readonly FakePlcLink _plc;
    private readonly ReplyLosingLink _link;

    public LostReplyWritesTests()
    {
        _plc = new FakePlcLink(_clock);
        _link = new ReplyLosingLink(_plc);
        _plc.Set(One, ProtocolArea.V, 10, 0x00, 0x07);
    }

    [Fact]
    public async Task Write_AppliedButReplyLost_ConfirmedByReadBackAndSentOnce()
    {
        var engine = await PolledEngineAsync("VW10");
        _link.NextWrite = WriteFate.AppliedReplyLost;

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VW10"), [0x00, 0x08]));

        outcome.Should().BeEquivalentTo(new WriteOutcome.ConfirmedByReadBack([0x00, 0x08], "no reply within 120 ms"));
        _link.Sent.OfType<WriteBlockRequest>().Should().ContainSingle("a write the PLC may have acted on is never repeated");
        _link.Sent.SkipWhile(r => r is not WriteBlockRequest).Skip(1).First().Should().BeOfType<ReadRequest>()
            .Which.Items.Should().Equal(new ReadItem(ProtocolArea.V, 10, 2));
        WriteLogLine().Should().Be("Write station 1 VW10: 16#0007 -> 16#0008 confirmed (reply lost, read back): no reply within 120 ms");
        engine.TryGetValue(One, PlcAddress.Parse("VW10"), out var shown).Should().BeTrue();
        shown.Raw.Should().Equal(0x00, 0x08);
    }

    [Fact]
    public async Task Write_RequestLostOnTheWay_NotAppliedWithTheOldValueAndNotResent()
    {
        var engine = await PolledEngineAsync("VW10");
        _link.NextWrite = WriteFate.RequestLost;

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VW10"), [0x00, 0x08]));

        outcome.Should().BeEquivalentTo(new WriteOutcome.NotApplied([0x00, 0x07], "no reply within 120 ms"));
        _link.Sent.OfType<WriteBlockRequest>().Should().ContainSingle();
        _plc.Memory(One, ProtocolArea.V)[10..12].Should().Equal(0x00, 0x07);
        var logged = _log.Events.Single(e => e.MessageTemplate.Text.StartsWith("Write station", StringComparison.Ordinal));
        logged.Level.Should().Be(LogEventLevel.Warning);
        logged.RenderMessage().Should().Be("Write station 1 VW10: 16#0007 -> 16#0008 not applied, read back 16#0007: no reply within 120 ms");
    }

    [Fact]
    public async Task Write_ReplyLostAndProgramChangedTheValue_UnknownNamingAllThreeValues()
    {
        var engine = await PolledEngineAsync("VW10");
        _link.NextWrite = WriteFate.AppliedReplyLost;
        _link.BetweenWriteAndReadBack = () => _plc.Set(One, ProtocolArea.V, 10, 0x00, 0x09);

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VW10"), [0x00, 0x08]));

        var unknown = outcome.Should().BeOfType<WriteOutcome.Unknown>().Subject;
        unknown.ReadBack.Should().Equal(0x00, 0x09);
        unknown.Detail.Should().Be("the PLC holds 16#0009, neither the old 16#0007 nor the new value: its program may have changed it");
    }

    [Fact]
    public async Task Write_ReplyLostAndReadBackFailsToo_UnknownAndNeverResent()
    {
        var engine = await PolledEngineAsync("VW10");
        _link.NextWrite = WriteFate.AppliedReplyLost;
        _link.BetweenWriteAndReadBack = () => _link.ReadBackFailure = new PlcCommunicationException(PlcErrorKind.NoAnswer, One, "no answer after 2 attempts");

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VW10"), [0x00, 0x08]));

        outcome.Should().BeEquivalentTo(new WriteOutcome.Unknown(default, "no reply within 120 ms", "the read-back failed too (NoAnswer: no answer after 2 attempts)"));
        _link.Sent.OfType<WriteBlockRequest>().Should().ContainSingle();
        engine.GetStationStatus(One).State.Should().Be(StationState.Offline);
        WriteLogLine().Should().Be(
            "Write station 1 VW10: 16#0007 -> 16#0008 unknown: no reply within 120 ms; the read-back failed too (NoAnswer: no answer after 2 attempts)");
    }

    [Fact]
    public async Task Write_PortNeverOpened_FailedAsNothingSent()
    {
        var engine = await PolledEngineAsync("VW10");
        _link.NextWrite = WriteFate.NeverSent;

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VW10"), [0x00, 0x08]));

        outcome.Should().BeEquivalentTo(new WriteOutcome.Failed("PortUnavailable: COM9 is gone; nothing was sent", WriteFailureKind.LinkFailure));
        _link.Sent.Should().NotContain(r => r is WriteBlockRequest);
    }

    [Fact]
    public async Task Write_PlcActedOnACorruptedCopy_CauseSaysAnotherAddressMayHaveBeenWritten()
    {
        var engine = await PolledEngineAsync("VW10");
        _link.NextWrite = WriteFate.AppliedToCorruptedCopy;

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VW10"), [0x00, 0x08]));

        outcome.Should().BeOfType<WriteOutcome.ConfirmedByReadBack>().Which.Cause.Should().Be(
            "no reply within 120 ms; the PLC acted on a corrupted copy of the request, so it may have written another address too: check the values near VW10");
    }

    [Fact]
    public async Task Write_BitReplyLost_ReadsItsByteBackAndJudgesTheBit()
    {
        _plc.Set(One, ProtocolArea.M, 2, 0b1000_0001);
        var engine = await PolledEngineAsync("M2.3");
        _link.NextWrite = WriteFate.RequestLost;

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bit(One, PlcAddress.Parse("M2.3"), true));

        outcome.Should().BeEquivalentTo(new WriteOutcome.NotApplied([0x00], "no reply within 120 ms"));
        _link.Sent.OfType<ReadRequest>().Last().Items.Should().Equal(new ReadItem(ProtocolArea.M, 2, 1));
    }

    [Fact]
    public async Task Write_ReplyLostOldValueNeverPolled_NotTheNewValueIsUnknown()
    {
        var engine = new PollingEngine(_link, PollPlanner.Build(Items(One, "VB0")), _clock, _log.CreateLogger());
        _link.NextWrite = WriteFate.RequestLost;

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VW10"), [0x00, 0x08]));

        outcome.Should().BeOfType<WriteOutcome.Unknown>().Which.Detail.Should().Be(
            "the PLC holds 16#0007, not the new value, and its old value was never read");
    }

    private async Task<PollingEngine> PolledEngineAsync(string address)
    {
        var engine = new PollingEngine(_link, PollPlanner.Build(Items(One, address)), _clock, _log.CreateLogger());
        await engine.RunCycleAsync(CancellationToken.None);
        return engine;
    }

    private string WriteLogLine() =>
        _log.Events.Single(e => e.MessageTemplate.Text.StartsWith("Write station", StringComparison.Ordinal)).RenderMessage();

    private static async Task<WriteOutcome> WriteThroughCycle(PollingEngine engine, WriteRequest request)
    {
        var write = engine.WriteAsync(request);
        await engine.RunCycleAsync(CancellationToken.None);
        return await write.Guarded();
    }
}
