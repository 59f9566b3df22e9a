using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V1;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Link;

/// <summary>A station silent to IDENTIFY v2 gets one v1 IDENTIFY; a v1 handler's answer becomes "regenerate the PLC code".</summary>
public sealed class PlcLinkV1ProbeTests
{
    private static readonly Station Station2 = new(2);
    private static readonly IdentifyRequest Identify = new(Station2);

    [Fact]
    public async Task Identify_V1HandlerAnswersTheProbe_FailsWithRegenerateTheCode()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{V2Identify}"
            < no response                                        // a v1 handler ignores v2 frames
            > "{Ascii(V1IdentifyProbe.Encode(Station2, 0x02))}"  // <020201..>: v1 IDENTIFY, XOR block check
            < "{V1Reply(0x02)}"
            """, clock);
        var link = NewLink(transport, clock);

        var failure = (await link.ExchangeAsync(Identify, default)).Failure!;

        failure.Message.Should().Be("station 2 runs Operator Panel handler protocol v1: regenerate the PLC code (opanel generate) and download it");
        failure.Message.Should().Be(HandlerV1.Message(Station2));
        failure.Kind.Should().Be(PlcErrorKind.HandlerOutdated);
        link.StatisticsFor(Station2).Should().BeEquivalentTo(new { Requests = 2, Replies = 1, Timeouts = 1 });
        transport.AssertComplete();
    }

    [Fact]
    public async Task Identify_ProbeAnsweredByAnotherStation_StaysNoAnswer()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{V2Identify}"
            < no response
            > "{Ascii(V1IdentifyProbe.Encode(Station2, 0x02))}"
            < "{V1Reply(0x02, station: 3)}"
            """, clock);
        var link = NewLink(transport, clock);

        var failure = (await link.ExchangeAsync(Identify, default)).Failure!;

        failure.Message.Should().StartWith("station 2 on scripted: no valid reply to Identify after 1 attempts");
    }

    [Fact]
    public async Task Identify_SilenceOfAStationThatAnsweredV2Before_SendsNoProbe()
    {
        var clock = new ManualTimeProvider();
        var read = new ReadRequest(Station2, [new ReadItem(ProtocolArea.M, 0, 1)]);
        var identify = Ascii(RequestCodec.Encode(Identify with { Sequence = 0x02 }));
        var transport = new ScriptedTransport($"""
            > "{Ascii(RequestCodec.Encode(read with { Sequence = 0x01 }))}"
            < "{Ascii(ResponseCodec.Encode(new ReadResponse(Station2, 0x01, [0x05]), read with { Sequence = 0x01 }))}"
            > "{identify}"
            < no response                                        // e.g. the IDENTIFY that confirms a STOP
            """, clock);
        var link = NewLink(transport, clock);
        await link.ExchangeAsync(read, default);

        var failure = (await link.ExchangeAsync(Identify, default)).Failure!;

        failure.Kind.Should().Be(PlcErrorKind.NoAnswer);
        transport.Written.Should().HaveCount(2, "no v1 probe after the IDENTIFY");
        transport.AssertComplete();
    }

    [Fact]
    public async Task Read_NoAnswer_SendsNoProbe()
    {
        var clock = new ManualTimeProvider();
        var read = new ReadRequest(Station2, [new ReadItem(ProtocolArea.M, 0, 1)]);
        var transport = new ScriptedTransport($"""
            > "{Ascii(RequestCodec.Encode(read with { Sequence = 0x01 }))}"
            < no response
            """, clock);
        var link = NewLink(transport, clock);

        (await link.ExchangeAsync(read, default)).Should().BeOfType<LinkReply.Failed>();

        transport.Written.Should().ContainSingle();
        transport.AssertComplete();
    }

    private static string V2Identify => Ascii(RequestCodec.Encode(Identify with { Sequence = 0x01 }));

    /// <summary>A v1 IDENTIFY reply: STATUS 00, PROTOCOL_VERSION 01, then v1's other 14 bytes (CPU 224, scan times...).</summary>
    private static string V1Reply(byte sequence, int station = 2) =>
        Ascii(V1IdentifyProbe.Frame([(byte)station, sequence, 0x81, 0x00, 0x01, 0x01, 0x03, 0x01, 0x0E, 0x77, 0x05, 0x20, 0x01, 0x00, 0x05, 0x00, 0x03, 0x00, 0x09]));

    private static PlcLink NewLink(ITransport transport, TimeProvider clock) =>
        new(transport, LinkOptions.For(Some.SerialSettings()) with { Retries = 0, InterFrameGap = TimeSpan.Zero }, clock);

    private static string Ascii(byte[] frame) => System.Text.Encoding.ASCII.GetString(frame);
}
