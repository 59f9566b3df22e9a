using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Line;

/// <summary>
/// Turns a project into byte pipes, one per serial port (one RS-485 bus, <see cref="Polling.ProjectBus"/>), for a
/// <see cref="ProjectLine"/>: real ports (<see cref="SerialLineConnector"/>), or simulated PLCs in demo mode and in tests.
/// The line never sees which.
/// </summary>
public interface ILineConnector
{
    /// <summary>
    /// Transports for every port of <paramref name="project"/>; they need not be open yet (the link opens a closed
    /// transport before each exchange, so a port that is missing now is reported as an offline station, not an error).
    /// </summary>
    Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken);
}
