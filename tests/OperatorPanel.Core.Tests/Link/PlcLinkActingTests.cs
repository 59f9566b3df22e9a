using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Link;

/// <summary>WRITE and WRITE BIT act on the process: the link sends them once and says whether the frame left the PC (so the PLC may have acted).</summary>
public sealed class PlcLinkActingTests
{
    private static readonly Station Station2 = new(2);
    private static readonly WriteBlockRequest WriteVw10 = new(Station2, ProtocolArea.V, 10, [0x00, 0x08]);
    private static readonly ReadRequest ReadMb0 = new(Station2, [new ReadItem(ProtocolArea.M, 0, 1)]);

    private static string Request => Ascii(RequestCodec.Encode(WriteVw10 with { Sequence = 0x01 }));

    [Fact]
    public async Task Exchange_WriteReplyTimesOut_ReplyLostAndNeverResent()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Request}"   // WRITE VW10 := 0008
            < no response   // the reply is lost: the PLC may have written
            """, clock);
        var link = NewLink(transport, clock);

        var reply = await link.ExchangeAsync(WriteVw10, default);

        var lost = reply.Should().BeOfType<LinkReply.Failed>().Subject;
        lost.Sent.Should().BeTrue("the frame went out: the PLC may have written");
        lost.Failure.Message.Should().StartWith("station 2 on scripted: no valid reply to Write sent once, never repeated (no reply within");
        lost.CorruptedCopy.Should().BeFalse();
        transport.Written.Should().ContainSingle("link retries are for requests that do not act on the process");
        link.StatisticsFor(Station2).Should().BeEquivalentTo(new { Requests = 1, Retries = 0, Timeouts = 1 });
        transport.AssertComplete();
    }

    [Fact]
    public async Task Exchange_WriteReplyGarbled_ReplyLost()
    {
        var clock = new ManualTimeProvider();
        var good = Ascii(ResponseCodec.Encode(new WriteBlockResponse(Station2, 0x01, [0x00, 0x08]), WriteVw10 with { Sequence = 0x01 }));
        var transport = new ScriptedTransport($"""
            > "{Request}"
            < "{good[..^4]}Z{good[^3..]}"   // noise made a character non-hex
            """, clock);
        var link = NewLink(transport, clock);

        var reply = await link.ExchangeAsync(WriteVw10, default);

        reply.Should().BeOfType<LinkReply.Failed>().Which.Should().Match<LinkReply.Failed>(f => f.Sent && f.Failure.Message.Contains("reply unusable"));
        transport.Written.Should().ContainSingle();
        link.StatisticsFor(Station2).CorruptFrames.Should().Be(1);
    }

    [Fact]
    public async Task Exchange_WriteReplyTimesOut_FailsWithNoAnswerWithoutResending()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Request}"
            < no response
            """, clock);
        var link = NewLink(transport, clock);

        var reply = await link.ExchangeAsync(WriteVw10, default);

        reply.Failure!.Kind.Should().Be(PlcErrorKind.NoAnswer);
        transport.Written.Should().ContainSingle();
    }

    [Fact]
    public async Task Exchange_WriteAnswered_ReturnsTheReply()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Request}"
            < "{Ascii(ResponseCodec.Encode(new WriteBlockResponse(Station2, 0x01, [0x00, 0x08]), WriteVw10 with { Sequence = 0x01 }))}"
            """, clock);
        var link = NewLink(transport, clock);

        var reply = await link.ExchangeAsync(WriteVw10, default);

        reply.Should().BeOfType<LinkReply.Answered>().Which.Response.Should().BeOfType<WriteBlockResponse>()
            .Which.ReadBack.Should().Equal(0x00, 0x08);
    }

    [Fact]
    public async Task Exchange_DeviceVanishedBeforeTheFrameLeft_NotSent()
    {
        var clock = new ManualTimeProvider();
        var transport = new UnpluggableTransport();
        var link = new PlcLink(transport, LinkOptions.For(Some.SerialSettings()) with { InterFrameGap = TimeSpan.Zero }, clock);
        await link.ExchangeAsync(ReadMb0, default);
        transport.Unplug();

        var reply = await link.ExchangeAsync(WriteVw10, default);

        reply.Should().BeOfType<LinkReply.Failed>().Which.Should().Match<LinkReply.Failed>(f => !f.Sent && f.Failure.Kind == PlcErrorKind.PortUnavailable);
    }

    [Theory]
    [InlineData(CommandCode.Write, true)]
    [InlineData(CommandCode.WriteBit, true)]
    [InlineData(CommandCode.Read, false)]
    [InlineData(CommandCode.Identify, false)]
    [InlineData(CommandCode.DefineList, false)]
    [InlineData(CommandCode.ReadList, false)]
    public void ActsOnProcess_OnlyCommandsThatChangeThePlc(CommandCode command, bool acts) =>
        PlcLink.ActsOnProcess(command).Should().Be(acts);

    private static PlcLink NewLink(ITransport transport, TimeProvider clock) =>
        new(transport, LinkOptions.For(Some.SerialSettings()) with { Retries = 2, InterFrameGap = TimeSpan.Zero }, clock);

    private static string Ascii(byte[] frame) => System.Text.Encoding.ASCII.GetString(frame);
}
