using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using Serilog;

namespace OperatorPanel.Core.Line;

/// <summary>One serial port per bus of the project (COM port with a PC/PPI cable or an FTDI radio module).</summary>
/// <param name="logger">Where a port's abandoned close is reported (SerialPortTransport).</param>
public sealed class SerialLineConnector(ILogger? logger = null) : ILineConnector
{
    public Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(project);
        var transports = ProjectBus.Of(project)
            .ToDictionary(bus => bus.Serial.PortName, bus => (ITransport)new SerialPortTransport(bus.Serial, logger), StringComparer.OrdinalIgnoreCase);
        return Task.FromResult(new LineConnection(transports));
    }
}
