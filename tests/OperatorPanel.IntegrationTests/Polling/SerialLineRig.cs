using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Transport;
using OperatorPanel.IntegrationTests.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.TestKit;

namespace OperatorPanel.IntegrationTests.Polling;

/// <summary>
/// A whole serial line in one process: socat pty pair; on one end SerialPortTransport + SimulatedPlcHost serving
/// reference PLCs (or any <see cref="ISimulatedLine"/>) on one bus; on the other SerialPortTransport + PlcLink + Bus, triggered mode, so each test
/// decides when a cycle runs. Real time throughout; every wait is bounded by <see cref="Limit"/>.
/// </summary>
internal sealed class SerialLineRig : IAsyncDisposable
{
    public static readonly TimeSpan Limit = TimeSpan.FromSeconds(3);

    private readonly SocatPtyPair _pty;
    private readonly CancellationTokenSource _stop = new();
    private Task _hostRun = Task.CompletedTask;

    private SerialLineRig(SocatPtyPair pty, PlcPortTap tap, Bus bus, SimulatedPlcHost host)
    {
        (_pty, Tap, Bus, Host) = (pty, tap, bus, host);
    }

    public PlcPortTap Tap { get; }

    public Bus Bus { get; }

    public SimulatedPlcHost Host { get; }

    public static Task<SerialLineRig> StartAsync(IReadOnlyList<ReferencePlc> plcs, IEnumerable<string> watched, int baud = 19200)
    {
        var bus = new BusSimulator();
        foreach (var plc in plcs)
        {
            bus.Attach(plc);
        }

        return StartAsync(new ReferenceLine(bus, []), [.. plcs.Select(p => (p.Config.Station, p.Config.Cpu))], watched, baud);
    }

    /// <summary>Any simulated line (the reference model, or generated .awl in the interpreter) serving <paramref name="stations"/>.</summary>
    public static async Task<SerialLineRig> StartAsync(
        ISimulatedLine line, IReadOnlyList<(Station Station, CpuProfile Cpu)> stations, IEnumerable<string> watched, int baud = 19200)
    {
        var pty = await SocatPtyPair.StartAsync();
        var plcSerial = new SerialSettings { PortName = pty.PathB, BaudRate = baud };
        var panelSerial = new SerialSettings { PortName = pty.PathA, BaudRate = baud };
        var tap = new PlcPortTap(new SerialPortTransport(plcSerial));
        await tap.OpenAsync(default);
        var items = stations.SelectMany(s => watched.Select(a => new WatchedItem(s.Station, PlcAddress.Parse(a))));
        var cpus = stations.ToDictionary(s => s.Station, s => s.Cpu);
        // A loaded 2-core CI machine can stall a thread for longer than one PLC scan; the wider allowance keeps the link from
        // retrying there, so the tests see one exchange per request (retries have their own tests with a manual clock).
        // The reference model answers within one scan, so no time is allowed for the generated handler's slices.
        var options = LinkOptions.For(panelSerial) with { ScanAllowance = TimeSpan.FromMilliseconds(400), HandlerScanAllowance = TimeSpan.Zero };
        var host = new SimulatedPlcHost(tap, line, TimeProvider.System);
        var bus = Bus.Start(new PlcLink(new SerialPortTransport(panelSerial), options), PollPlanner.Build(items, cpus), new BusSettings { Mode = RefreshMode.OnDemand });
        var rig = new SerialLineRig(pty, tap, bus, host);
        rig._hostRun = Task.Run(() => rig.Host.RunAsync(rig._stop.Token));
        return rig;
    }

    /// <summary>
    /// Reference v3 stations on <paramref name="line"/>, polled by the panel's v3 link (Bus.StartV3) over the pty pair;
    /// lists on, on demand.
    /// </summary>
    public static async Task<SerialLineRig> StartV3Async(V3ReferenceLine line, IEnumerable<string> watched, int baud = 19200)
    {
        var pty = await SocatPtyPair.StartAsync();
        var plcSerial = new SerialSettings { PortName = pty.PathB, BaudRate = baud };
        var panelSerial = new SerialSettings { PortName = pty.PathA, BaudRate = baud };
        var tap = new PlcPortTap(new SerialPortTransport(plcSerial));
        await tap.OpenAsync(default);
        var stations = line.Stations.Select(s => (s.Setup.Station, s.Setup.Cpu)).ToList();
        var items = stations.SelectMany(s => watched.Select(a => new WatchedItem(s.Station, PlcAddress.Parse(a))));
        var options = LinkOptions.For(panelSerial) with { ScanAllowance = TimeSpan.FromMilliseconds(400), HandlerScanAllowance = TimeSpan.Zero };
        var host = new SimulatedPlcHost(tap, line, TimeProvider.System);
        var plan = PollPlanner.Build(items, stations.ToDictionary(s => s.Station, s => s.Cpu));
        var bus = Bus.StartV3(new V3Link(new SerialPortTransport(panelSerial), options), plan, new BusSettings { Mode = RefreshMode.OnDemand });
        var rig = new SerialLineRig(pty, tap, bus, host);
        rig._hostRun = Task.Run(() => rig.Host.RunAsync(rig._stop.Token));
        return rig;
    }

    public static ReferencePlc Plc(int station) =>
        new(new HandlerConfig(new Station(station), CpuProfiles.For(CpuModel.Cpu226)));

    /// <summary>One full cycle, bounded.</summary>
    public Task<PollResult> RefreshAsync() => Bus.RefreshAsync().WaitAsync(Limit);

    /// <summary>
    /// Full cycles until <paramref name="done"/> holds after one, within <see cref="Limit"/>; the last result either way.
    /// A busy test machine can make one exchange miss its reply timeout, and the next cycle must then show the state.
    /// </summary>
    public async Task<PollResult> RefreshUntilAsync(Func<PollResult, bool> done)
    {
        var started = TimeProvider.System.GetTimestamp();
        while (true)
        {
            var result = await RefreshAsync();
            if (done(result) || TimeProvider.System.GetElapsedTime(started) > Limit)
            {
                return result;
            }
        }
    }

    public PolledValue Value(ReferencePlc plc, string address) => Value(plc.Config.Station, address);

    public PolledValue Value(Station station, string address) =>
        Bus.TryGetValue(station, PlcAddress.Parse(address), out var value)
            ? value
            : throw new InvalidOperationException($"{address} is not watched");

    public StationState State(ReferencePlc plc) => State(plc.Config.Station);

    public StationState State(Station station) => Bus.StatusOf(station).State;

    public async ValueTask DisposeAsync()
    {
        await Bus.StopPollingAsync().WaitAsync(Limit);
        await _stop.CancelAsync();
        try
        {
            await _hostRun.WaitAsync(Limit);
        }
        catch (OperationCanceledException)
        {
            // The host ends its run with the cancellation: the expected way to stop it.
        }

        await Bus.DisposeAsync();
        await Tap.DisposeAsync();
        _pty.Dispose();
        _stop.Dispose();
    }
}
