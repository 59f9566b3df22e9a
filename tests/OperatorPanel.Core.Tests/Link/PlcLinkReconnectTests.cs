using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Link;

/// <summary>The link gets its port back after the device vanished: reopened, at most once per reopen interval.</summary>
public sealed class PlcLinkReconnectTests
{
    private static readonly Station Station2 = new(2);
    private static readonly ReadRequest ReadMb0 = new(Station2, [new ReadItem(ProtocolArea.M, 0, 1)]);
    private static readonly TimeSpan Interval = ReconnectOptions.Default.ReopenInterval;

    [Fact]
    public async Task Exchange_DeviceVanished_FailsWithTheVanishedPortMarkedReconnecting()
    {
        var (clock, transport, link) = Connected();
        await link.ExchangeAsync(ReadMb0, default);
        transport.Unplug();

        var failure = await FailsAsync(link.ExchangeAsync(ReadMb0, default));

        failure.Message.Should().Be(
            "station 2: serial port /dev/ttyUSB0: discard input failed: Input/output error (EIO) - the device vanished (unplugged?) - reconnecting");
        link.Outage.Should().Be("serial port /dev/ttyUSB0: discard input failed: Input/output error (EIO) - the device vanished (unplugged?) - reconnecting");
        clock.ActiveTimers.Should().Be(0);
    }

    [Fact]
    public async Task Exchange_WhileTheDeviceIsAway_ReopensAtMostOncePerIntervalAndKeepsReportingTheVanishedDevice()
    {
        var (clock, transport, link) = Connected();
        await link.ExchangeAsync(ReadMb0, default);
        transport.Unplug();
        await FailsAsync(link.ExchangeAsync(ReadMb0, default));
        await FailsAsync(link.ExchangeAsync(ReadMb0, default));
        transport.OpenAttempts.Should().Be(2, "one open to connect, one right after the failure");

        var waiting = link.ExchangeAsync(ReadMb0, default);
        clock.Advance(Interval - TimeSpan.FromMilliseconds(1));

        waiting.IsCompleted.Should().BeFalse("the next open waits out the reopen interval");
        transport.OpenAttempts.Should().Be(2);
        clock.Advance(TimeSpan.FromMilliseconds(1));
        var thrown = await FailsAsync(waiting);
        transport.OpenAttempts.Should().Be(3);
        thrown.Message.Should().EndWith("discard input failed: Input/output error (EIO) - the device vanished (unplugged?) - reconnecting",
            "the status keeps naming the vanished device, not each failed reopen");
    }

    [Fact]
    public async Task Exchange_DeviceAwayForFiveSeconds_CostsOneOpenPerIntervalNotABusyLoop()
    {
        var (clock, transport, link) = Connected();
        await link.ExchangeAsync(ReadMb0, default);
        transport.Unplug();
        var started = clock.GetUtcNow();

        while (clock.GetUtcNow() - started < TimeSpan.FromSeconds(5))
        {
            // A poller asking every 10 ms: while the link waits out the interval, only the clock moves.
            var exchange = link.ExchangeAsync(ReadMb0, default);
            clock.Advance(TimeSpan.FromMilliseconds(10));
            while (clock.ActiveTimers > 0)
            {
                clock.Advance(TimeSpan.FromMilliseconds(10));
            }

            await FailsAsync(exchange);
        }

        // 1 to connect, then one at the failure and one per 500 ms in 5 s.
        transport.OpenAttempts.Should().BeInRange(10, 12);
    }

    [Fact]
    public async Task Exchange_DeviceBack_ReopensWithinTheIntervalAndReadsTheCurrentValue()
    {
        var (clock, transport, link) = Connected();
        transport.Mb0 = 0x11;
        await link.ExchangeAsync(ReadMb0, default);
        transport.Unplug();
        await FailsAsync(link.ExchangeAsync(ReadMb0, default));
        await FailsAsync(link.ExchangeAsync(ReadMb0, default));
        transport.Mb0 = 0x22;
        transport.PlugIn();

        var exchange = link.ExchangeAsync(ReadMb0, default);
        clock.Advance(Interval);

        (await exchange).Response.Should().BeOfType<ReadResponse>().Which.Data.Should().Equal(0x22);
        link.Outage.Should().BeNull();
        transport.OpenAttempts.Should().Be(3);
    }

    [Fact]
    public async Task Exchange_PortMissingFromTheStart_KeepsTheOpenFailureWithoutReconnecting()
    {
        var clock = new ManualTimeProvider();
        var transport = new UnpluggableTransport();
        transport.Unplug();
        var link = NewLink(transport, clock);

        var thrown = await FailsAsync(link.ExchangeAsync(ReadMb0, default));

        thrown.Message.Should().Be("station 2: serial port /dev/ttyUSB0: open failed: No such file or directory (ENOENT) - no such port");
        link.Outage.Should().BeNull();
    }

    private static (ManualTimeProvider Clock, UnpluggableTransport Transport, PlcLink Link) Connected()
    {
        var clock = new ManualTimeProvider();
        var transport = new UnpluggableTransport();
        return (clock, transport, NewLink(transport, clock));
    }

    private static async Task<PlcCommunicationException> FailsAsync(Task<LinkReply> exchange)
    {
        var failure = (await exchange).Failure;
        failure.Should().NotBeNull("the port is gone: the exchange must come back failed, not answered");
        failure!.Kind.Should().Be(PlcErrorKind.PortUnavailable);
        return failure;
    }

    private static PlcLink NewLink(ITransport transport, TimeProvider clock) =>
        new(transport, LinkOptions.For(Some.SerialSettings()) with { InterFrameGap = TimeSpan.Zero }, clock);
}
