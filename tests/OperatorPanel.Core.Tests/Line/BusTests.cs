using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Line;

/// <summary>The bus's one queue: polling, IDENTIFY and writes from several callers go on the wire one at a time.</summary>
public sealed class BusTests
{
    private static readonly Station Station2 = new(2);
    private static readonly PlcAddress Mb0 = PlcAddress.Parse("MB0");

    [Fact]
    public async Task Bus_IdentifyAndRefreshAskedAtOnce_OnlyOneRequestIsOnTheWire()
    {
        var clock = new ManualTimeProvider();
        var pair = new InMemoryTransportPair(clock);
        await pair.BusSide.OpenAsync(default);
        var link = new PlcLink(pair.PanelSide, LinkOptions.For(Some.SerialSettings()) with { InterFrameGap = TimeSpan.Zero }, clock);
        await using var bus = Bus.OnDemand(link, PollPlanner.Build([new WatchedItem(Station2, Mb0)]), clock);
        var identify = new IdentifyRequest(Station2, 0x01);
        var read = new ReadRequest(Station2, 0x02, [new ReadItem(ProtocolArea.M, 0, 1)]);

        var identified = bus.IdentifyAsync(Station2);
        var refreshed = bus.RefreshAsync();
        var onWire = await FreeportWire.ReadFrameAsync(pair.BusSide);
        var nothingMore = await pair.BusSide.ReadAsync(new byte[64], TimeSpan.Zero, default);

        onWire.Should().Be(Ascii(RequestCodec.Encode(identify)), "the queue's job goes ahead of the cycle");
        nothingMore.Should().Be(0, "the READ waits for the IDENTIFY reply");
        await pair.BusSide.WriteAsync(ResponseCodec.Encode(Identity(0x01), identify), default);
        (await identified).Response.Should().BeOfType<IdentifyResponse>();
        (await FreeportWire.ReadFrameAsync(pair.BusSide)).Should().Be(Ascii(RequestCodec.Encode(read)));
        await pair.BusSide.WriteAsync(ResponseCodec.Encode(new ReadResponse(Station2, 0x02, [0x2A]), read), default);
        (await refreshed).FramesFailed.Should().Be(0);
        bus.TryGetValue(Station2, Mb0, out var value).Should().BeTrue();
        value.Raw.Should().Equal(0x2A);
    }

    /// <summary>A CPU 224 handler without READ CHANGES copies (docs/protocol-v2.md, IDENTIFY worked example, FEATURES 0).</summary>
    private static IdentifyResponse Identity(byte sequence) =>
        new(Station2, sequence, 2, 1, 3, 1, 0x3C, 116, 5, 0x20, 1, 3, 2, 9, 0, 7764, 428, 0, 0);

    private static string Ascii(byte[] frame) => FreeportWire.Text(frame);
}
