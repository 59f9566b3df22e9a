using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>
/// The simulated line of <paramref name="inner"/>, whose close does not return until <see cref="Release"/>: a serial port
/// hanging in its close, as USB adapters' drivers do.
/// </summary>
internal sealed class HangingCloseConnector(ILineConnector inner) : ILineConnector
{
    public TaskCompletionSource Release { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

    public async Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken)
    {
        var opened = await inner.ConnectAsync(project, cancellationToken);
        var transports = ProjectBus.Of(project).ToDictionary(b => b.Serial.PortName, b => opened.TransportFor(b.Serial.PortName));
        return new LineConnection(transports, async () =>
        {
            await Release.Task;
            await opened.DisposeAsync();
        });
    }
}
