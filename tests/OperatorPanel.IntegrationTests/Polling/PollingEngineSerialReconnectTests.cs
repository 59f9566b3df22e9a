using System.Diagnostics;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.TestKit;
using Xunit.Abstractions;

namespace OperatorPanel.IntegrationTests.Polling;

/// <summary>
/// The USB-serial adapter pulled and plugged back, over socat: the pty pair is killed (both ends vanish) and a new
/// pair is started on the same link paths, the simulated protocol v3 PLC serving the new end. Real time, every wait bounded and
/// polled in short steps.
/// </summary>
public sealed class PollingEngineSerialReconnectTests(ITestOutputHelper output)
{
    private static readonly TimeSpan PollStep = TimeSpan.FromMilliseconds(20);
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(3);
    private static readonly TimeSpan RecoveryLimit = TimeSpan.FromSeconds(2);
    private static readonly PlcAddress Mb0 = PlcAddress.Parse("MB0");

    [Fact]
    public async Task Watch_DeviceVanishesAndReturnsUnderTheSameName_StaleMeanwhileThenGoodWithTheNewValueWithinTwoSeconds()
    {
        var plc = V3.V3Rig.Handler(2);
        var station = plc.Setup.Station;
        plc.Memory.M[0] = 0x11;
        using var stop = new CancellationTokenSource();
        var first = await SocatPtyPair.StartAsync();
        var (panelPath, plcPath) = (first.PathA, first.PathB);
        var plcPort = new SerialPortTransport(new SerialSettings { PortName = plcPath, BaudRate = 19200 });
        var panelCharacter = new SerialSettings { PortName = panelPath, BaudRate = 19200 }.CharacterTime;
        var host = new SimulatedPlcHost(plcPort, new V3ReferenceLine([plc]) { CharacterTime = panelCharacter }, TimeProvider.System);
        var panelSerial = new SerialSettings { PortName = panelPath, BaudRate = 19200 };
        var (log, sink) = CollectingSink.CreateLogger();
        var link = new V3Link(
            new SerialPortTransport(panelSerial), V3LinkOptions.For(panelSerial) with { ScanAllowance = TimeSpan.FromMilliseconds(400) }, log: log);
        var plan = PollPlanner.Build([new WatchedItem(station, Mb0)], new Dictionary<Station, Core.Cpu.CpuProfile> { [station] = plc.Setup.Cpu });
        var hostRun = Task.Run(() => host.RunAsync(stop.Token));
        await using var bus = Bus.StartV3(link, plan, new BusSettings { Mode = RefreshMode.Continuous, MinimumPeriod = TimeSpan.FromMilliseconds(100) }, logger: log);
        SocatPtyPair? second = null;
        try
        {
            (await WaitForAsync(() => Value(bus, station) is { Quality: ValueQuality.Good } v && v.Raw[0] == 0x11, Limit))
                .Should().BeTrue("the line works before the adapter is pulled");

            first.Kill();
            var lost = await WaitForAsync(() => Value(bus, station).Quality == ValueQuality.Stale, Limit);
            await hostRun.Invoking(r => r.WaitAsync(Limit)).Should().ThrowAsync<PlcCommunicationException>("the PLC's end vanished too");

            lost.Should().BeTrue("values go stale when the port vanishes");
            var status = bus.StatusOf(station);
            status.State.Should().Be(StationState.Offline);
            status.LastError.Should().StartWith($"PortUnavailable: station 2: serial port {panelPath}: ")
                .And.EndWith("the device vanished (unplugged?) - reconnecting");
            Value(bus, station).Raw.Should().Equal(0x11);

            // Away for a while: reopen attempts fail, the value stays stale, the status keeps naming the vanished device.
            plc.Memory.M[0] = 0x22;
            var away = Stopwatch.StartNew();
            while (away.Elapsed < TimeSpan.FromSeconds(1))
            {
                Value(bus, station).Quality.Should().Be(ValueQuality.Stale);
                await Task.Delay(PollStep);
            }

            bus.StatusOf(station).LastError.Should().EndWith("the device vanished (unplugged?) - reconnecting");
            second = await SocatPtyPair.StartAsync(panelPath, plcPath);
            var back = Stopwatch.StartNew();
            output.WriteLine($"{DateTimeOffset.Now:HH:mm:ss.fff} the pty pair is back");
            await plcPort.OpenAsync(default).WaitAsync(Limit);
            output.WriteLine($"{DateTimeOffset.Now:HH:mm:ss.fff} the PLC's end is open again");
            hostRun = Task.Run(() => host.RunAsync(stop.Token));
            var recovered = await WaitForAsync(() => Value(bus, station) is { Quality: ValueQuality.Good } v && v.Raw[0] == 0x22, Limit);
            output.WriteLine($"good again {back.ElapsedMilliseconds} ms after the pty pair was back");

            recovered.Should().BeTrue("the link reopens the port once the device is back");
            back.Elapsed.Should().BeLessThan(RecoveryLimit);
            bus.StatusOf(station).State.Should().Be(StationState.Online);
            link.Outage.Should().BeNull();
        }
        finally
        {
            foreach (var logged in sink.Events)
            {
                output.WriteLine($"{logged.Timestamp:HH:mm:ss.fff} {logged.Level} {logged.RenderMessage(System.Globalization.CultureInfo.InvariantCulture)}");
            }

            await bus.StopPollingAsync().WaitAsync(Limit);
            await stop.CancelAsync();
            try
            {
                await hostRun.WaitAsync(Limit);
            }
            catch (OperationCanceledException)
            {
                // The host ends its run with the cancellation: the expected way to stop it.
            }

            await plcPort.DisposeAsync();
            first.Dispose();
            second?.Dispose();
        }
    }

    private static PolledValue Value(Bus bus, Station station) =>
        bus.TryGetValue(station, Mb0, out var value) ? value : throw new InvalidOperationException("MB0 is not watched");

    private static async Task<bool> WaitForAsync(Func<bool> condition, TimeSpan limit)
    {
        var watch = Stopwatch.StartNew();
        while (!condition())
        {
            if (watch.Elapsed > limit)
            {
                return false;
            }

            await Task.Delay(PollStep);
        }

        return true;
    }
}
