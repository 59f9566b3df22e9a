using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Link;

/// <summary>
/// REQCHECK: a reply whose request check is not the check of the request sent answered a corrupted copy. A refusal of
/// such a copy is noise, not a refusal (retried once); a refusal with our check, or one that repeats, is real.
/// </summary>
public sealed class PlcLinkRequestCheckTests
{
    private static readonly Station Station2 = new(2);
    private static readonly ReadRequest ReadMb0 = new(Station2, [new ReadItem(ProtocolArea.M, 0, 1)]);
    private static readonly WriteBlockRequest WriteVw10 = new(Station2, ProtocolArea.V, 10, [0x00, 0x08]);

    /// <summary>The check of a request that noise changed into another valid frame (READ MB1 instead of MB0).</summary>
    private static readonly ushort CorruptedCheck = RequestCodec.Check(new ReadRequest(Station2, 0x01, [new ReadItem(ProtocolArea.M, 1, 1)]));

    [Fact]
    public async Task Exchange_RefusalOfACorruptedCopy_RetriedOnceAndCountedNotAsARefusal()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Frame(ReadMb0)}"
            < "{Refusal(CommandCode.Read, CorruptedCheck)}"   // BadLength, but for another frame than ours
            > "{Frame(ReadMb0)}"                              // retried once
            < "{Ascii(ResponseCodec.Encode(new ReadResponse(Station2, 0x01, [0x42]), ReadMb0 with { Sequence = 0x01 }))}"
            """, clock);
        var link = NewLink(transport, clock, retries: 0);

        var response = (await link.ExchangeAsync(ReadMb0, default)).Response;

        response.Should().BeOfType<ReadResponse>().Which.Data.Should().Equal(0x42);
        link.StatisticsFor(Station2).Should().BeEquivalentTo(new { CorruptedRefusals = 1, NegativeReplies = 0, Retries = 1 });
        transport.AssertComplete();
    }

    [Fact]
    public async Task Exchange_CorruptedRefusalRepeats_TakenAsARealRefusal()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Frame(ReadMb0)}"
            < "{Refusal(CommandCode.Read, CorruptedCheck)}"
            > "{Frame(ReadMb0)}"
            < "{Refusal(CommandCode.Read, CorruptedCheck)}"
            """, clock);
        var link = NewLink(transport, clock, retries: 2);

        var response = (await link.ExchangeAsync(ReadMb0, default)).Response;

        response.Should().BeOfType<ErrorResponse>().Which.Error.Should().Be(ProtocolError.BadLength);
        transport.Written.Should().HaveCount(2, "a refusal that repeats is real: no third attempt");
        link.StatisticsFor(Station2).Should().BeEquivalentTo(new { CorruptedRefusals = 2, NegativeReplies = 1 });
    }

    [Fact]
    public async Task Exchange_RefusalWithTheRequestsOwnCheck_IsRealAtOnce()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Frame(ReadMb0)}"
            < "{Refusal(CommandCode.Read, RequestCodec.Check(ReadMb0 with { Sequence = 0x01 }))}"
            """, clock);
        var link = NewLink(transport, clock, retries: 2);

        var response = (await link.ExchangeAsync(ReadMb0, default)).Response;

        response.Should().BeOfType<ErrorResponse>().Which.Error.Should().Be(ProtocolError.BadLength);
        transport.Written.Should().ContainSingle();
        link.StatisticsFor(Station2).CorruptedRefusals.Should().Be(0);
    }

    [Fact]
    public async Task Exchange_WriteRefusedAsACorruptedCopy_RetriedOnceBecauseThePlcDidNothing()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Frame(WriteVw10)}"
            < "{Refusal(CommandCode.Write, CorruptedCheck)}"
            > "{Frame(WriteVw10)}"
            < "{Ascii(ResponseCodec.Encode(new WriteBlockResponse(Station2, 0x01, [0x00, 0x08]), WriteVw10 with { Sequence = 0x01 }))}"
            """, clock);
        var link = NewLink(transport, clock, retries: 2);

        var reply = await link.ExchangeAsync(WriteVw10, default);

        reply.Should().BeOfType<LinkReply.Answered>().Which.Response.Should().BeOfType<WriteBlockResponse>();
        transport.AssertComplete();
    }

    [Fact]
    public async Task Exchange_WriteAnsweredForACorruptedCopy_ReplyLostMarkedCorruptedAndNotResent()
    {
        var clock = new ManualTimeProvider();
        var executedElsewhere = new WriteBlockResponse(Station2, 0x01, [0x00, 0x08]) { RequestCheck = CorruptedCheck };
        var transport = new ScriptedTransport($"""
            > "{Frame(WriteVw10)}"
            < "{Ascii(ResponseCodec.Encode(executedElsewhere))}"   // STATUS 00: the PLC wrote, but not our frame
            """, clock);
        var link = NewLink(transport, clock, retries: 2);

        var reply = await link.ExchangeAsync(WriteVw10, default);

        var lost = reply.Should().BeOfType<LinkReply.Failed>().Subject;
        lost.Sent.Should().BeTrue();
        lost.CorruptedCopy.Should().BeTrue();
        lost.Failure.Message.Should().Contain($"the reply's REQCHECK 16#{CorruptedCheck:X4} is not the request's").And.Contain("the PLC acted on a corrupted copy");
        transport.Written.Should().ContainSingle();
    }

    [Fact]
    public async Task Exchange_ReadAnsweredForACorruptedCopy_RetriedAsACorruptFrame()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Frame(ReadMb0)}"
            < "{Ascii(ResponseCodec.Encode(new ReadResponse(Station2, 0x01, [0x99]) { RequestCheck = CorruptedCheck }))}"   // MB1's value
            > "{Frame(ReadMb0)}"
            < "{Ascii(ResponseCodec.Encode(new ReadResponse(Station2, 0x01, [0x42]), ReadMb0 with { Sequence = 0x01 }))}"
            """, clock);
        var link = NewLink(transport, clock, retries: 1);

        var response = (await link.ExchangeAsync(ReadMb0, default)).Response;

        response.Should().BeOfType<ReadResponse>().Which.Data.Should().Equal(0x42);
        link.StatisticsFor(Station2).CorruptFrames.Should().Be(1);
    }

    private static string Frame(PlcRequest request) => Ascii(RequestCodec.Encode(request with { Sequence = 0x01 }));

    private static string Refusal(CommandCode command, ushort requestCheck) =>
        Ascii(ResponseCodec.Encode(new ErrorResponse(Station2, 0x01, command, ProtocolError.BadLength) { RequestCheck = requestCheck }));

    private static PlcLink NewLink(ITransport transport, TimeProvider clock, int retries) =>
        new(transport, LinkOptions.For(Some.SerialSettings()) with { Retries = retries, InterFrameGap = TimeSpan.Zero }, clock);

    private static string Ascii(byte[] frame) => System.Text.Encoding.ASCII.GetString(frame);
}
