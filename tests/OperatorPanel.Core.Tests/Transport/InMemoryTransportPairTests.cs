using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Transport;

public sealed class InMemoryTransportPairTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromMilliseconds(200);
    private readonly ManualTimeProvider _clock = new();

    [Fact]
    public async Task Write_PanelSide_ArrivesExactlyOnBusSide()
    {
        var (panel, bus) = await OpenPairAsync();
        await panel.WriteAsync(Hex.Ascii("<0101017E>"), default);

        var buffer = new byte[64];
        var count = await bus.ReadAsync(buffer, Timeout, default);

        buffer[..count].Should().Equal(Hex.Ascii("<0101017E>"));
    }

    [Fact]
    public async Task Write_BusSide_ArrivesOnPanelSide()
    {
        var (panel, bus) = await OpenPairAsync();
        await bus.WriteAsync(Hex.Parse("3C 30 31 3E"), default);

        var buffer = new byte[2];
        var first = await panel.ReadAsync(buffer, Timeout, default);

        first.Should().Be(2);
        buffer.Should().Equal(Hex.Parse("3C 30"));
    }

    [Fact]
    public async Task Read_NothingSent_ReturnsZeroWhenClockPassesTimeout()
    {
        var (panel, _) = await OpenPairAsync();
        var read = panel.ReadAsync(new byte[8], Timeout, default);

        _clock.Advance(Timeout - TimeSpan.FromMilliseconds(1));
        read.IsCompleted.Should().BeFalse();
        _clock.Advance(TimeSpan.FromMilliseconds(1));

        (await read).Should().Be(0);
        _clock.ActiveTimers.Should().Be(0);
    }

    [Fact]
    public async Task Read_BytesArriveWhileWaiting_ReturnsThemBeforeTimeout()
    {
        var (panel, bus) = await OpenPairAsync();
        var buffer = new byte[8];
        var read = panel.ReadAsync(buffer, Timeout, default);

        await bus.WriteAsync(Hex.Parse("3E"), default);

        (await read).Should().Be(1);
        buffer[0].Should().Be(0x3E);
    }

    [Fact]
    public async Task Read_Canceled_ThrowsOperationCanceled()
    {
        var (panel, _) = await OpenPairAsync();
        using var cancel = new CancellationTokenSource();
        var read = panel.ReadAsync(new byte[8], Timeout, cancel.Token);

        await cancel.CancelAsync();

        await read.Invoking(r => r).Should().ThrowAsync<OperationCanceledException>();
    }

    [Fact]
    public async Task DiscardInput_StaleBytes_AreDropped()
    {
        var (panel, bus) = await OpenPairAsync();
        await bus.WriteAsync(Hex.Ascii("<stale>"), default);

        panel.DiscardInput();
        var read = panel.ReadAsync(new byte[8], Timeout, default);
        _clock.Advance(Timeout);

        (await read).Should().Be(0);
    }

    [Fact]
    public async Task Close_OneEnd_OtherEndsReadAndWriteFailWithPortUnavailable()
    {
        var (panel, bus) = await OpenPairAsync();
        var pendingRead = bus.ReadAsync(new byte[8], Timeout, default);

        panel.Close();

        (await pendingRead.Invoking(r => r).Should().ThrowAsync<PlcCommunicationException>())
            .Which.Kind.Should().Be(PlcErrorKind.PortUnavailable);
        (await bus.Invoking(b => b.WriteAsync(new byte[1], default)).Should().ThrowAsync<PlcCommunicationException>())
            .Which.Message.Should().Contain("memory:bus").And.Contain("memory:panel");
        bus.IsOpen.Should().BeFalse();
    }

    [Fact]
    public async Task Read_BeforeOpen_IsAProgrammingError()
    {
        var pair = new InMemoryTransportPair(_clock);

        await pair.PanelSide.Invoking(p => p.ReadAsync(new byte[1], Timeout, default))
            .Should().ThrowAsync<InvalidOperationException>();
    }

    private async Task<(InMemoryTransport Panel, InMemoryTransport Bus)> OpenPairAsync()
    {
        var pair = new InMemoryTransportPair(_clock);
        await pair.PanelSide.OpenAsync(default);
        await pair.BusSide.OpenAsync(default);
        return (pair.PanelSide, pair.BusSide);
    }
}
