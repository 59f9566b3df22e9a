using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using Serilog;

namespace OperatorPanel.Cli.Link;

/// <summary>
/// Simulated PLCs on one RS-485 bus, each optionally running the demo bottling process; what <c>opanel simulate</c>
/// serves on a serial device and what <c>--demo</c> serves in-process.
/// </summary>
internal sealed class SimulatedLine
{
    private SimulatedLine(BusSimulator bus, IReadOnlyList<DemoProcess> processes)
    {
        Bus = bus;
        Processes = processes;
    }

    public BusSimulator Bus { get; }

    public IReadOnlyList<DemoProcess> Processes { get; }

    public static SimulatedLine Create(IEnumerable<HandlerConfig> stations, bool runProcess)
    {
        var bus = new BusSimulator();
        var processes = new List<DemoProcess>();
        foreach (var config in stations)
        {
            var plc = CreateStation(config);
            bus.Attach(plc);
            if (runProcess)
            {
                processes.Add(new DemoProcess(plc));
            }
        }

        return new SimulatedLine(bus, processes);
    }

    /// <summary>Runs the processes ahead by <paramref name="time"/> so the first reply already shows a running line.</summary>
    public void WarmUp(TimeSpan time)
    {
        foreach (var process in Processes)
        {
            process.Advance(time);
        }
    }

    public SimulatedPlcHost HostOn(ITransport port, TimeProvider time, ILogger log) => new(port, Bus, Processes, time, log);

    /// <summary>The one place the station model is chosen (the reference model; a later switch may add the STL one).</summary>
    private static ReferencePlc CreateStation(HandlerConfig config) => new(config);
}
