using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using Serilog;

namespace OperatorPanel.Demo;

/// <summary>
/// The App's demo and <c>opanel watch --demo</c>: a <see cref="DemoLine"/> per bus of the project, simulating its stations
/// with their own CPUs and protocol 3 handlers (STOP where the project allows it, so Stop PLC can be tried; compact where
/// the project says so; at the project's "handlerVFirst") and the demo process. Every bus of
/// the connection allows <see cref="DemoLine.HostAllowance"/> on its replies. A station that cannot be simulated stops
/// the connect with the reason, and nothing stays running.
/// </summary>
public sealed class DemoLineConnector(SimulationModel model, ILogger log) : ILineConnector
{
    public async Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(project);
        var demos = new List<DemoLine>();
        var transports = new Dictionary<string, ITransport>(StringComparer.OrdinalIgnoreCase);
        foreach (var bus in ProjectBus.Of(project))
        {
            var stations = bus.Stations.Select(s => new HandlerConfig(s.Address, s.Cpu, allowStop: s.AllowStop) { Compact = s.Compact, V3First = s.HandlerVFirst });
            if (!DemoLine.TryStart(bus.Serial, stations, model, log, out var demo, out var error))
            {
                await StopAsync(demos).ConfigureAwait(false);
                throw new InvalidOperationException(error);
            }

            demos.Add(demo);
            transports[bus.Serial.PortName] = demo.PanelSide;
        }

        return new LineConnection(transports, () => StopAsync(demos)) { ScanAllowance = DemoLine.HostAllowance };
    }

    private static async ValueTask StopAsync(List<DemoLine> demos)
    {
        foreach (var demo in demos)
        {
            await demo.DisposeAsync().ConfigureAwait(false);
        }
    }
}
