using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Line;

/// <summary>
/// The line without a PLC: a triggered project on an in-memory port whose far end nobody reads, so nothing is exchanged
/// and every value stays not read. What is tested is who hears what, and when.
/// </summary>
public sealed class ProjectLineTests
{
    private static readonly Station Two = new(2);
    private static readonly PlcAddress Vw10 = PlcAddress.Parse("VW10");
    private readonly ManualTimeProvider _clock = new();

    [Fact]
    public async Task Subscribe_BeforeConnect_HearsTheValueNowThenOnConnectAndOnDisconnect()
    {
        var heard = new List<PolledValue>();
        var line = new ProjectLine(Project(), time: _clock);

        using var subscription = line.Subscribe(Two, Vw10, heard.Add);
        await line.ConnectAsync(new PairConnector(_clock));
        line.TryGetValue(Two, Vw10, out _).Should().BeTrue("a connected line watches VW10");
        await line.DisconnectAsync();

        heard.Should().HaveCount(3, "subscribe, connect and disconnect each hand the subscriber the value of the moment");
        heard.Should().OnlyContain(v => !v.HasValue && v.Quality == ValueQuality.Bad);
        line.TryGetValue(Two, Vw10, out _).Should().BeFalse("a disconnected line has no values");
    }

    [Fact]
    public async Task Subscribe_OneSubscriberThrows_TheOthersStillHearAndTheErrorIsLogged()
    {
        var (logger, sink) = CollectingSink.CreateLogger();
        var heard = new List<PolledValue>();
        var line = new ProjectLine(Project(), time: _clock, logger: logger);
        var broken = false;
        using var first = line.Subscribe(Two, Vw10, _ =>
        {
            if (broken)
            {
                throw new InvalidOperationException("view model bug");
            }
        });
        using var second = line.Subscribe(Two, Vw10, heard.Add);
        broken = true;

        await line.ConnectAsync(new PairConnector(_clock));
        await line.DisconnectAsync();

        heard.Should().HaveCount(3, "subscribe, connect and disconnect: the broken subscriber stops nobody");
        sink.Events.Should().Contain(e => e.Level == Serilog.Events.LogEventLevel.Error && e.Exception!.Message == "view model bug");
    }

    [Fact]
    public async Task Subscribe_Disposed_HearsNothingMore()
    {
        var heard = new List<PolledValue>();
        var line = new ProjectLine(Project(), time: _clock);
        line.Subscribe(Two, Vw10, heard.Add).Dispose();

        await line.ConnectAsync(new PairConnector(_clock));
        await line.DisconnectAsync();

        heard.Should().ContainSingle("only the value at subscription time arrived");
    }

    [Fact]
    public async Task StateChanged_ConnectAndDisconnect_RaisedThroughDeliverEachTime()
    {
        var delivered = 0;
        var raised = 0;
        var line = new ProjectLine(Project(), new ProjectLineOptions { Deliver = work => { delivered++; work(); } }, _clock);
        line.StateChanged += (_, _) => raised++;

        await line.ConnectAsync(new PairConnector(_clock));
        await line.DisconnectAsync();

        (delivered, raised).Should().Be((2, 2), "the status bar hears of connect and disconnect, inside the delivery of the values");
    }

    [Fact]
    public async Task Edit_StationsChangeWhileConnected_RefusedThenTakenOnceDisconnected()
    {
        var line = new ProjectLine(Project(), time: _clock);
        await line.ConnectAsync(new PairConnector(_clock));
        var moved = Project() with { Stations = [Project().Stations[0] with { Address = new Station(3) }] };

        var whileConnected = () => line.EditAsync(moved);

        await whileConnected.Should().ThrowAsync<InvalidOperationException>().WithMessage("*disconnect*");
        line.Project.Stations[0].Address.Should().Be(Two);
        await line.DisconnectAsync();
        await line.EditAsync(moved);
        line.Project.Should().Be(moved);
    }

    [Fact]
    public async Task Connect_ConnectionWithScanAllowance_EveryReplyIsWaitedForThatMuchLonger()
    {
        // The demo line's connection asks for a second more per reply (DemoLine.HostAllowance): every attempt that timed
        // out waited that second longer than on a real port, and so did the two probes for an older handler (a v2 and a
        // v1 IDENTIFY) the v3 link sends after an IDENTIFY nobody answered.
        var (plain, plainTimeouts) = await TimeToGiveUpAsync(TimeSpan.Zero);
        var (allowed, timeouts) = await TimeToGiveUpAsync(TimeSpan.FromSeconds(1));

        timeouts.Should().Be(plainTimeouts).And.BePositive();
        var waits = timeouts + 2;
        (allowed - plain).TotalMilliseconds.Should().BeApproximately(waits * 1000, 10 * waits);
    }

    /// <summary>Simulated time from a triggered refresh to its end when nothing answers; the clock moves only while the link waits.</summary>
    private static async Task<(TimeSpan Waited, long Timeouts)> TimeToGiveUpAsync(TimeSpan allowance)
    {
        var clock = new ManualTimeProvider();
        var line = new ProjectLine(Project(), time: clock);
        await line.ConnectAsync(new PairConnector(clock) { ScanAllowance = allowance });
        var start = clock.GetUtcNow();
        var refresh = line.RefreshAsync(CancellationToken.None);
        var guard = System.Diagnostics.Stopwatch.StartNew();
        while (!refresh.IsCompleted && guard.Elapsed < TimeSpan.FromSeconds(30))
        {
            if (clock.ActiveTimers > 0)
            {
                clock.Advance(TimeSpan.FromMilliseconds(5));
            }

            await Task.Yield();
        }

        await refresh;
        var waited = clock.GetUtcNow() - start;
        var timeouts = line.StatisticsFor(Two).Timeouts;
        await line.DisconnectAsync();
        return (waited, timeouts);
    }

    private static PanelProject Project() => new(
        "Line",
        new RefreshSettings(RefreshMode.OnDemand, TimeSpan.FromMilliseconds(100)),
        [
            new ProjectStation(
                "Filler", Two, Some.Cpu(), new SerialSettings { PortName = "COM7" },
                [], [], [new ProjectTag("Speed", Vw10, DisplayFormat.Signed, Writable: true, Description: string.Empty)], []),
        ]);

    /// <summary>One in-memory port per bus; the bus end is never read, as if no PLC were attached.</summary>
    private sealed class PairConnector(TimeProvider time) : ILineConnector
    {
        public TimeSpan ScanAllowance { get; init; }

        public Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken) =>
            Task.FromResult(new LineConnection(ProjectBus.Of(project).ToDictionary(
                b => b.Serial.PortName, b => (ITransport)new InMemoryTransportPair(time, b.Serial.PortName, b.Serial.PortName + " bus").PanelSide))
            {
                ScanAllowance = ScanAllowance,
            });
    }
}
