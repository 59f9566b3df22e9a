using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Stop;

namespace OperatorPanel.ViewModels.Session;

/// <summary>Remote STOP of one station (docs/protocol-v2.md, "07 STOP"), refused in read-only mode like every write.</summary>
public sealed partial class PanelSession
{
    /// <summary>
    /// Sends STOP through the station's bus beside the polling (Core/Stop/RemoteStop: IDENTIFY, 07 once, IDENTIFY), which
    /// logs it as "RUN -> STOP by operator"; a station the project does not allow to stop, or any station in read-only
    /// mode, gets nothing. The outcome also goes to the status line.
    /// </summary>
    public async Task<StopOutcome> StopAsync(Station station, CancellationToken cancellationToken = default)
    {
        var project = Project.Stations.FirstOrDefault(s => s.Address == station);
        StopOutcome outcome = project switch
        {
            null => new StopOutcome.NotSent(station, "not in the project"),
            { AllowStop: false } => new StopOutcome.NotSent(station, $"the project does not allow STOP for {project.Name}"),
            _ when IsReadOnly => new StopOutcome.NotSent(station, "read-only mode, nothing sent"),
            _ => await _line.StopAsync(station, cancellationToken),
        };
        if (outcome.IsStopped)
        {
            StatusLine.Show(outcome.Text);
        }
        else
        {
            StatusLine.ShowError(outcome.Text);
        }

        return outcome;
    }
}
