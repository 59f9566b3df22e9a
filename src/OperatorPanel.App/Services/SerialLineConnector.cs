using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.App.Services;

/// <summary>One serial port per bus of the project (COM port with a PC/PPI cable or an FTDI radio module).</summary>
public sealed class SerialLineConnector : ILineConnector
{
    public Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(project);
        var transports = ProjectBus.Of(project)
            .ToDictionary(bus => bus.Serial.PortName, bus => (ITransport)new SerialPortTransport(bus.Serial), StringComparer.OrdinalIgnoreCase);
        return Task.FromResult(new LineConnection(transports));
    }
}
