using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using Serilog;

namespace OperatorPanel.Cli.Link;

/// <summary>
/// <c>opanel watch --demo</c>: a <see cref="DemoLine"/> per bus of the project, simulating its stations with their own CPUs
/// and the demo process. A station that cannot be simulated stops the connect with the reason, and nothing stays running.
/// </summary>
internal sealed class DemoLineConnector(SimulationModel model, ILogger log) : ILineConnector
{
    public async Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken)
    {
        var demos = new List<DemoLine>();
        var transports = new Dictionary<string, ITransport>(StringComparer.OrdinalIgnoreCase);
        foreach (var bus in ProjectBus.Of(project))
        {
            var stations = bus.Stations.Select(s => new HandlerConfig(s.Address, s.Cpu, allowStop: s.AllowStop));
            if (!DemoLine.TryStart(bus.Serial, stations, model, log, out var demo, out var error))
            {
                await StopAsync(demos);
                throw new InvalidOperationException(error);
            }

            demos.Add(demo);
            transports[bus.Serial.PortName] = demo.PanelSide;
        }

        return new LineConnection(transports, () => StopAsync(demos));
    }

    private static async ValueTask StopAsync(List<DemoLine> demos)
    {
        foreach (var demo in demos)
        {
            await demo.DisposeAsync();
        }
    }
}
