using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.ViewModels.Session;
using Serilog;

namespace OperatorPanel.App.Services;

/// <summary>
/// Demo mode: every bus of the project gets simulated PLCs running the bottle-filler demo process behind an in-memory
/// pipe, served on real time; the panel talks to the pipe exactly as to a serial port.
/// </summary>
public sealed class DemoLineConnector(ILogger log) : ILineConnector
{
    /// <summary>The process starts this far in, so the first values already show a running line.</summary>
    private static readonly TimeSpan WarmUp = TimeSpan.FromSeconds(2);

    public Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(project);
        var transports = new Dictionary<string, ITransport>(StringComparer.OrdinalIgnoreCase);
        var hosts = new List<Task>();
        var stop = new CancellationTokenSource();
        foreach (var bus in ProjectBus.Of(project))
        {
            var simulated = new BusSimulator();
            var processes = new List<DemoProcess>();
            foreach (var station in bus.Stations)
            {
                var plc = new ReferencePlc(new HandlerConfig(station.Address, station.Cpu));
                simulated.Attach(plc);
                var process = new DemoProcess(plc);
                process.Advance(WarmUp);
                processes.Add(process);
            }

            var pair = new InMemoryTransportPair(TimeProvider.System, $"{bus.Serial.PortName} (demo)", $"{bus.Serial.PortName} (demo bus)");
            var host = new SimulatedPlcHost(pair.BusSide, simulated, processes, TimeProvider.System, log);
            hosts.Add(Task.Run(() => host.RunAsync(stop.Token), CancellationToken.None));
            transports[bus.Serial.PortName] = pair.PanelSide;
        }

        return Task.FromResult(new LineConnection(transports, () => StopAsync(stop, hosts)));
    }

    private static async ValueTask StopAsync(CancellationTokenSource stop, List<Task> hosts)
    {
        await stop.CancelAsync();
        try
        {
            await Task.WhenAll(hosts);
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
            // The hosts end by cancellation; that is the normal way out.
        }

        stop.Dispose();
    }
}
