using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Reference.V3;
using OperatorPanel.TestKit;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>
/// Puts a protocol v3 <see cref="ReferenceHandler"/> for every station of the project on a simulated line per port. The
/// PLCs are created once (the first connect) so a reconnect finds the same memory; <see cref="Configure"/> changes a
/// station's handler (its CPU, STOP, write mask, compact).
/// </summary>
internal sealed class SimulatedLineConnector(ManualTimeProvider clock) : ILineConnector
{
    private readonly Dictionary<string, SimulatedTransport> _transports = new(StringComparer.OrdinalIgnoreCase);
    private readonly Dictionary<int, ReferenceHandler> _plcs = [];
    private readonly Dictionary<int, HandlerConfig> _configs = [];

    public int Connects { get; private set; }

    public IReadOnlyDictionary<int, ReferenceHandler> Plcs => _plcs;

    public SimulatedTransport Transport(string port) => _transports[port];

    public ReferenceHandler Plc(int station) => _plcs[station];

    /// <summary>Before the first connect: a station that runs a protocol v1 handler (<see cref="SimulatedTransport.V1Handler"/>).</summary>
    public Station? V1Handler { get; set; }

    /// <summary>Before the first connect: the handler a station runs (another CPU, another write mask).</summary>
    public void Configure(HandlerConfig config) => _configs[config.Station.Address] = config;

    public Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken)
    {
        Connects++;
        foreach (var bus in ProjectBus.Of(project))
        {
            if (!_transports.ContainsKey(bus.Serial.PortName))
            {
                var handlers = new List<ReferenceHandler>();
                foreach (var station in bus.Stations)
                {
                    var config = _configs.GetValueOrDefault(station.Address.Address) ?? new HandlerConfig(station.Address, station.Cpu);
                    var plc = new ReferenceHandler(config.V3SetupFor(bus.Serial));
                    _plcs[station.Address.Address] = plc;
                    handlers.Add(plc);
                }

                _transports[bus.Serial.PortName] = new SimulatedTransport(bus.Serial.PortName, new V3ReferenceLine(handlers), clock)
                {
                    V1Handler = bus.Stations.Any(s => s.Address == V1Handler) ? V1Handler : null,
                };
            }
        }

        return Task.FromResult(new LineConnection(_transports.ToDictionary(t => t.Key, t => (ITransport)t.Value)));
    }
}
