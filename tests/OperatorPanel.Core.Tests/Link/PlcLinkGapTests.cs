using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Link;

/// <summary>The minimum gap: after any frame's '&gt;' or a timeout, the next '&lt;' waits at least max(5 ms, 3 characters).</summary>
public sealed class PlcLinkGapTests
{
    private static readonly Station Station2 = new(2);
    private static readonly ReadRequest ReadMb0 = new(Station2, [new ReadItem(ProtocolArea.M, 0, 1)]);

    [Theory]
    [InlineData(9600, LinkKind.Cable, 5.0)]
    [InlineData(19200, LinkKind.Cable, 5.0)]
    [InlineData(2400, LinkKind.Cable, 12.5)]
    [InlineData(1200, LinkKind.Cable, 25.0)]
    [InlineData(9600, LinkKind.RadioModule, 20.0)]
    public void For_Line_KeepsTheLongerOfFiveMsThreeCharactersAndTheMediumsGap(int baud, LinkKind kind, double gapMs)
    {
        // 8N1: 10 bits a character; 1200 baud: 8.33 ms, 3 characters 25 ms. The radio module keeps its 20 ms.
        var options = LinkOptions.For(Some.SerialSettings(baud, kind));

        options.InterFrameGap.TotalMilliseconds.Should().BeApproximately(gapMs, 0.001);
        options.InterFrameGap.Should().BeGreaterThanOrEqualTo(options.MinimumGap);
    }

    [Fact]
    public async Task Exchange_RightAfterAReply_WaitsTheGapBeforeTheNextStartCharacter()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Frame(1)}"
            < "{Reply(1)}"
            > "{Frame(2)}"
            < "{Reply(2)}"
            """, clock);
        var link = new PlcLink(transport, LinkOptions.For(Some.SerialSettings()), clock);
        await link.ExchangeAsync(ReadMb0, default);

        var second = link.ExchangeAsync(ReadMb0, default);
        clock.Advance(TimeSpan.FromMilliseconds(4.9));
        var writtenBeforeTheGap = transport.Written.Count;
        clock.Advance(TimeSpan.FromMilliseconds(0.1));
        await second.WaitAsync(TimeSpan.FromSeconds(10));

        writtenBeforeTheGap.Should().Be(1, "5 ms after the reply's '>' have not passed");
        transport.Written.Should().HaveCount(2);
        transport.AssertComplete();
    }

    [Fact]
    public async Task Exchange_RetryAfterATimeout_WaitsTheGapAfterTheTimeout()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport($"""
            > "{Frame(1)}"
            < no response
            > "{Frame(1)}"
            < "{Reply(1)}"
            """, clock);
        var link = new PlcLink(transport, LinkOptions.For(Some.SerialSettings(1200)) with { Retries = 1 }, clock);

        var exchange = link.ExchangeAsync(ReadMb0, default);
        var writtenAtTheTimeout = transport.Written.Count;
        clock.Advance(TimeSpan.FromMilliseconds(24.9));
        var writtenBeforeTheGap = transport.Written.Count;
        clock.Advance(TimeSpan.FromMilliseconds(0.1));
        await exchange.WaitAsync(TimeSpan.FromSeconds(10));

        (writtenAtTheTimeout, writtenBeforeTheGap).Should().Be((1, 1), "at 1200 baud the gap is 3 characters, 25 ms");
        transport.Written.Should().HaveCount(2);
    }

    private static string Frame(byte sequence) => Ascii(RequestCodec.Encode(ReadMb0 with { Sequence = sequence }));

    private static string Reply(byte sequence) => Ascii(ResponseCodec.Encode(new ReadResponse(Station2, sequence, [0x42])));

    private static string Ascii(byte[] frame) => System.Text.Encoding.ASCII.GetString(frame);
}
