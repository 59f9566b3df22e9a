using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// Turns a project into byte pipes, one per serial port (one RS-485 bus, <see cref="Core.Polling.ProjectBus"/>). The App
/// implements it with serial ports, or with the simulated PLC in demo mode; tests with the simulator. The view models
/// never see which.
/// </summary>
public interface ILineConnector
{
    /// <summary>
    /// Transports for every port of <paramref name="project"/>; they need not be open yet (the link opens a closed
    /// transport before each exchange, so a port that is missing now is reported as an offline station, not an error).
    /// </summary>
    Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken);
}
