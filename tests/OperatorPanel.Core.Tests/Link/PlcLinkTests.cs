using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V1;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;
using Serilog.Events;

namespace OperatorPanel.Core.Tests.Link;

/// <summary>
/// The link against annotated scripts. Frames are the worked examples' shape: station 02, READ of MB0 (1 byte), under
/// SEQ 01, the number a new link stamps on its first request.
/// </summary>
public sealed class PlcLinkTests
{
    private static readonly Station Station2 = new(2);
    private static readonly ReadRequest ReadMb0 = new(Station2, [new ReadItem(ProtocolArea.M, 0, 1)]);

    private static string Request => Ascii(RequestCodec.Encode(ReadMb0 with { Sequence = 0x01 }));

    private static string Reply(byte data, byte sequence = 0x01) =>
        Ascii(ResponseCodec.Encode(new ReadResponse(Station2, sequence, [data]), ReadMb0 with { Sequence = sequence }));

    [Fact]
    public async Task Exchange_StationAnswers_ReturnsDecodedReplyAndCountsIt()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Request}"   // READ MB0
            < "{Reply(0x81)}"
            """, clock);
        var link = NewLink(transport, clock);

        var reply = await link.ExchangeAsync(ReadMb0, default);

        reply.Should().BeOfType<LinkReply.Answered>().Which.Response.Should().BeOfType<ReadResponse>().Which.Data.Should().Equal(0x81);
        link.StatisticsFor(Station2).Should().BeEquivalentTo(new { Requests = 1, Replies = 1, Retries = 0, Timeouts = 0 });
        transport.AssertComplete();
    }

    [Fact]
    public async Task Exchange_FirstAttemptTimesOut_ResendsTheIdenticalFrame()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Request}"
            < no response
            > "{Request}"   // the retry: same bytes, same SEQ
            < "{Reply(0x05)}"
            """, clock);
        var link = NewLink(transport, clock);

        var response = (await link.ExchangeAsync(ReadMb0, default)).Response!;

        ((ReadResponse)response).Data.Should().Equal(0x05);
        transport.Written.Should().HaveCount(2);
        transport.Written[1].Should().Equal(transport.Written[0]);
        link.StatisticsFor(Station2).Should().BeEquivalentTo(new { Requests = 2, Replies = 1, Retries = 1, Timeouts = 1 });
    }

    [Fact]
    public async Task Exchange_NoReplyToAnyAttempt_FailsWithNoAnswerNamingStation()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Request}"
            < no response
            > "{Request}"
            < no response
            > "{Request}"
            < no response
            """, clock);
        var link = NewLink(transport, clock);

        var reply = await link.ExchangeAsync(ReadMb0, default);

        var failed = reply.Should().BeOfType<LinkReply.Failed>().Subject;
        failed.Sent.Should().BeTrue();
        failed.Failure.Kind.Should().Be(PlcErrorKind.NoAnswer);
        failed.Failure.Station.Should().Be(Station2);
        failed.Failure.Message.Should().Contain("station 2 on scripted: no valid reply to Read after 3 attempts");
        link.StatisticsFor(Station2).Should().BeEquivalentTo(new { Requests = 3, Replies = 0, Retries = 2, Timeouts = 3 });
    }

    [Fact]
    public async Task Exchange_StationStaysSilent_LogsEachFailureAtDebugForTheStationStatesToReport()
    {
        var clock = new ManualTimeProvider();
        var second = Ascii(RequestCodec.Encode(ReadMb0 with { Sequence = 0x02 }));
        var transport = new ScriptedTransport(string.Join('\n', new[] { Request, second }.SelectMany(frame => Enumerable.Repeat($"""
            > "{frame}"
            < no response
            """, 3))), clock);
        var (log, sink) = CollectingSink.CreateLogger();
        var link = new PlcLink(transport, LinkOptions.For(Some.SerialSettings()) with { Retries = 2, InterFrameGap = TimeSpan.Zero }, clock, log);

        for (var i = 0; i < 2; i++)
        {
            (await link.ExchangeAsync(ReadMb0, default)).Should().BeOfType<LinkReply.Failed>();
        }

        // The station falling silent is news once, from the bus's station states (StationTracker), not from the link.
        var failures = sink.Events.Where(e => e.RenderMessage().Contains("no valid reply to Read")).Select(e => e.Level);
        failures.Should().Equal(LogEventLevel.Debug, LogEventLevel.Debug);
    }

    [Fact]
    public async Task Exchange_SilenceAfterTheStationAcknowledgedStop_IsLoggedAtDebugNotAsNews()
    {
        var clock = new ManualTimeProvider();
        var stop = new StopRequest(Station2, 0x01);
        var identify = Ascii(RequestCodec.Encode(new IdentifyRequest(Station2, 0x02)));
        var transport = new ScriptedTransport($"""
            > "{Ascii(RequestCodec.Encode(stop))}"
            < "{Ascii(ResponseCodec.Encode(new StopResponse(Station2, 0x01), stop))}"
            > "{identify}"
            < no response
            > "{identify}"
            < no response
            > "{identify}"
            < no response
            """, clock);
        var (log, sink) = CollectingSink.CreateLogger();
        var link = new PlcLink(transport, LinkOptions.For(Some.SerialSettings()) with { Retries = 2, InterFrameGap = TimeSpan.Zero }, clock, log);

        (await link.ExchangeAsync(stop, default)).Should().BeOfType<LinkReply.Answered>();
        (await link.ExchangeAsync(new IdentifyRequest(Station2), default)).Should().BeOfType<LinkReply.Failed>();

        sink.Events.Where(e => e.RenderMessage().Contains("no valid reply to Identify")).Select(e => e.Level).Should().Equal(LogEventLevel.Debug);
        transport.AssertComplete();
    }

    [Fact]
    public async Task Exchange_ReplyWithBadChecksum_CountsCorruptAndRetries()
    {
        var clock = new ManualTimeProvider();
        var good = Reply(0x07);
        var corrupt = good[..^3] + (good[^3] == '0' ? '1' : '0') + good[^2..];
        var transport = new ScriptedTransport($"""
            > "{Request}"
            < "{corrupt}"   // one check character hit by noise
            > "{Request}"
            < "{good}"
            """, clock);
        var link = NewLink(transport, clock);

        var response = (await link.ExchangeAsync(ReadMb0, default)).Response!;

        ((ReadResponse)response).Data.Should().Equal(0x07);
        link.StatisticsFor(Station2).CorruptFrames.Should().Be(1);
    }

    [Fact]
    public async Task Exchange_LateReplyToOlderRequestAndOwnEcho_AreSkipped()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Request}"
            < "{Request}"             // RS-485 adapter echoing our own request
            < "{Reply(0x11, 0xFF)}"   // late reply to SEQ FF, an earlier request
            < "xx{Reply(0x33)}"       // noise, then the real reply
            """, clock);
        var link = NewLink(transport, clock);

        var response = (await link.ExchangeAsync(ReadMb0, default)).Response!;

        ((ReadResponse)response).Data.Should().Equal(0x33);
        link.StatisticsFor(Station2).Should().BeEquivalentTo(new { Requests = 1, Replies = 1, CorruptFrames = 0 });
    }

    [Fact]
    public async Task Exchange_StationRefuses_ReturnsErrorResponseAndCountsIt()
    {
        var clock = new ManualTimeProvider();
        var refusal = Ascii(ResponseCodec.Encode(new ErrorResponse(Station2, 0x01, CommandCode.Read, ProtocolError.AddressOutOfRange), ReadMb0 with { Sequence = 0x01 }));
        var transport = new ScriptedTransport($"""
            > "{Request}"
            < "{refusal}"
            """, clock);
        var link = NewLink(transport, clock);

        var response = (await link.ExchangeAsync(ReadMb0, default)).Response!;

        response.Should().BeEquivalentTo(new ErrorResponse(Station2, 0x01, CommandCode.Read, ProtocolError.AddressOutOfRange)
        {
            RequestCheck = RequestCodec.Check(ReadMb0 with { Sequence = 0x01 }),
        });
        link.StatisticsFor(Station2).NegativeReplies.Should().Be(1);
    }

    [Fact]
    public async Task Exchange_PortVanished_FailsWithPortUnavailableNamingTheStation()
    {
        var clock = new ManualTimeProvider();
        var pair = new InMemoryTransportPair(clock);
        await pair.PanelSide.OpenAsync(default);
        await pair.BusSide.OpenAsync(default);
        var link = new PlcLink(pair.PanelSide, LinkOptions.For(Some.SerialSettings()), clock);
        pair.BusSide.Close();

        var reply = await link.ExchangeAsync(ReadMb0, default);

        reply.Failure.Should().Match<PlcCommunicationException>(f => f.Kind == PlcErrorKind.PortUnavailable && f.Station == Station2);
    }

    [Fact]
    public async Task Statistics_WhileAFrameIsInFlight_CountTheRequestOnlyOnceItHasEnded()
    {
        var clock = new ManualTimeProvider();
        var pair = new InMemoryTransportPair(clock);
        await pair.BusSide.OpenAsync(default);
        var link = new PlcLink(pair.PanelSide, LinkOptions.For(Some.SerialSettings()) with { InterFrameGap = TimeSpan.Zero }, clock);

        var exchange = link.ExchangeAsync(ReadMb0, default);
        (await FreeportWire.ReadFrameAsync(pair.BusSide)).Should().Be(Request);
        var inFlight = link.StatisticsFor(Station2);
        await pair.BusSide.WriteAsync(Hex.Ascii(Reply(0x01)), default);
        await exchange;

        inFlight.Should().BeEquivalentTo(new { Requests = 0, Replies = 0 }, "the screen drawn mid-exchange must not show a request without its outcome");
        link.StatisticsFor(Station2).Should().BeEquivalentTo(new { Requests = 1, Replies = 1 });
    }

    [Fact]
    public async Task Exchange_EveryRequestIdentifyIncluded_GoesOutUnderTheLinksNextSequenceWhateverTheCallerSet()
    {
        var clock = new ManualTimeProvider();
        var identify = new IdentifyRequest(Station2, 0x01);
        var transport = new ScriptedTransport($"""
            > "{Request}"                                                        // SEQ 01
            < "{Reply(0x10)}"
            > "{Ascii(RequestCodec.Encode(identify with { Sequence = 0x02 }))}"   // IDENTIFY under SEQ 02, not the caller's 01
            < no response
            > "{Ascii(RequestCodec.Encode(identify with { Sequence = 0x02 }))}"   // its retry keeps SEQ 02
            < no response
            > "{Ascii(RequestCodec.Encode(identify with { Sequence = 0x02 }))}"
            < no response
            > "{Ascii(RequestCodec.Encode(ReadMb0 with { Sequence = 0x03 }))}"    // SEQ 03 (no v1 probe: it answered v2)
            < "{Reply(0x99, 0x02)}"                                             // late answer to SEQ 02: skipped
            < "{Reply(0x30, 0x03)}"
            """, clock);
        var link = NewLink(transport, clock);

        var first = (await link.ExchangeAsync(ReadMb0, default)).Response!;
        (await link.ExchangeAsync(identify, default)).Should().BeOfType<LinkReply.Failed>();
        var third = (await link.ExchangeAsync(ReadMb0, default)).Response!;

        first.Sequence.Should().Be(0x01);
        ((ReadResponse)third).Data.Should().Equal(0x30);
        third.Sequence.Should().Be(0x03);
        transport.AssertComplete();
    }

    [Theory]
    [InlineData(LinkKind.Cable, 742.08)]
    [InlineData(LinkKind.RadioModule, 1069.16)]
    public void ReplyTimeout_Identify9600_IsLineTimePlusDelayScansMediumAndMargin(LinkKind kind, double milliseconds)
    {
        // IDENTIFY: 12 request + 62 reply characters, 10 bits each at 9600 baud = 77.08 ms; + 5 ms delay + 100 ms scan
        // + 18 handler scans (5 + 2 + 11) x 30 ms + 20 ms margin; a radio module adds 250 ms and the line time once more.
        var options = LinkOptions.For(Some.SerialSettings(9600, kind));

        options.ReplyTimeoutFor(new IdentifyRequest(Station2, 1)).TotalMilliseconds.Should().BeApproximately(milliseconds, 0.01);
    }

    private static PlcLink NewLink(ITransport transport, TimeProvider clock) =>
        new(transport, LinkOptions.For(Some.SerialSettings()) with { Retries = 2, InterFrameGap = TimeSpan.Zero }, clock);

    private static string Ascii(byte[] frame) => FreeportWire.Text(frame);
}
