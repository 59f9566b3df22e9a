using System.Diagnostics;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.TestKit;
using static OperatorPanel.Simulator.Tests.Hosting.StlStations;

namespace OperatorPanel.Simulator.Tests.Hosting;

/// <summary>
/// The host maps a manual clock onto an STL line: the request goes on the line when it is read, the CPUs run to the
/// clock's time, and the reply reaches the transport only once its characters have left at the baud rate.
/// </summary>
public sealed class SimulatedPlcHostTests
{
    /// <summary>A hang guard for the host's turn on the thread pool; the test's time is the manual clock.</summary>
    private static readonly TimeSpan HangGuard = TimeSpan.FromSeconds(5);

    [Fact]
    public async Task RunAsync_StlLineOnManualClock_ReplyArrivesOnlyAfterRequestDelayAndReplyCharacters()
    {
        var time = new ManualTimeProvider();
        var pair = new InMemoryTransportPair(time);
        await pair.PanelSide.OpenAsync(default);
        var line = Line(runProcess: false, 2);
        var origin = line.Now;
        var start = time.GetTimestamp();
        var host = new SimulatedPlcHost(pair.BusSide, line, time);
        using var stop = new CancellationTokenSource();
        var run = Task.Run(() => host.RunAsync(stop.Token));
        await SettleAsync(() => time.ActiveTimers == 1);

        var request = Identify(2);
        await pair.PanelSide.WriteAsync(request, default);
        await SettleAsync(() => line.FramesReceived == 1 && time.ActiveTimers == 1);
        var early = await AdvanceAsync(time, line, (origin, start), TimeSpan.FromMilliseconds(14), pair.PanelSide);
        var late = await AdvanceAsync(time, line, (origin, start), TimeSpan.FromMilliseconds(400), pair.PanelSide);
        await stop.CancelAsync();
        await FluentActions.Awaiting(() => run).Should().ThrowAsync<OperationCanceledException>();

        early.Should().BeEmpty("the 12-character request ends after 12.5 ms, the reply waits 5 ms more and its first character takes 1 ms");
        FrameCodec.TryDecode(late, out var reply, out var error).Should().BeTrue(error.ToString());
        (reply.Station, reply.Command).Should().Be((2, (byte)((byte)CommandCode.Identify | FreeportFrame.ReplyBit)));
        host.Replies.Should().Be(1);
        line.Now.Should().Be(origin + TimeSpan.FromMilliseconds(400));
    }

    /// <summary>
    /// Advances the clock 2 ms (the host's idle poll) at a time to <paramref name="until"/> after the host started (simulated time
    /// <c>Origin</c>, clock <c>Start</c>), letting the host take each turn; what the panel received.
    /// </summary>
    private static async Task<byte[]> AdvanceAsync(ManualTimeProvider time, StlLine line, (TimeSpan Origin, long Start) host, TimeSpan until, InMemoryTransport panel)
    {
        while (line.Now < host.Origin + until)
        {
            time.Advance(TimeSpan.FromMilliseconds(2));
            var expected = host.Origin + time.GetElapsedTime(host.Start);
            await SettleAsync(() => line.Now >= expected && time.ActiveTimers == 1);
        }

        var buffer = new byte[512];
        var count = await panel.ReadAsync(buffer, TimeSpan.Zero, default);
        return buffer[..count];
    }

    private static async Task SettleAsync(Func<bool> settled)
    {
        var guard = Stopwatch.StartNew();
        while (!settled())
        {
            guard.Elapsed.Should().BeLessThan(HangGuard, "the host should take its turn");
            await Task.Yield();
        }
    }
}
