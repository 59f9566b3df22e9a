using OperatorPanel.Core.Line;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// "Read over PPI" (docs/ppi.md section 14): a Freeport bus whose station fell silent (STOP, TERM) reconnects with that
/// bus switched in memory to PPI, which the CPU answers without our handler; "Back to Freeport" reconnects as saved.
/// One click, not automatic: reopening the port at 8E1 silences the bus's other stations that still answer Freeport.
/// </summary>
public sealed partial class PanelSession
{
    /// <summary>The project's links as saved while a bus is read over PPI; null otherwise.</summary>
    private PanelProject? _freeportLinks;

    /// <summary>A bus of the project is read over PPI in place of its handler (the project file still says Freeport).</summary>
    public bool IsReadingOverPpi => _freeportLinks is not null;

    /// <summary>The project to save: <see cref="Project"/> with the links as saved while a bus is read over PPI.</summary>
    public PanelProject SavedProject => _freeportLinks is { } saved ? PpiFallback.Restore(Project, saved) : Project;

    /// <summary>
    /// The first Freeport station on a cable whose handler is silent (health Stopped) on a connected line; null when none.
    /// Not over a radio module: the modules carry the handler's Freeport frames, PPI needs the cable (LinkReader).
    /// </summary>
    public StationStatusViewModel? SilentFreeportStation =>
        IsConnected ? Stations.FirstOrDefault(CanReadOverPpi) : null;

    /// <summary>The station is a Freeport station on a cable whose handler fell silent.</summary>
    public static bool CanReadOverPpi(StationStatusViewModel station)
    {
        ArgumentNullException.ThrowIfNull(station);
        return !station.IsPpi && station.Station.Link.Kind == LinkKind.Cable && station.Health == StationHealth.Stopped;
    }

    /// <summary>
    /// Reconnects with <paramref name="station"/>'s bus switched to PPI (<see cref="PpiFallback"/>); the project is not
    /// edited and not marked unsaved. Says on the status line what it does and at which baud.
    /// </summary>
    public async Task ReadOverPpiAsync(StationStatusViewModel station, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(station);
        var connector = _connector;
        if (!IsConnected || connector is null || !CanReadOverPpi(station))
        {
            return;
        }

        var link = station.Station.Link;
        var saved = SavedProject;
        await RelinkAsync(PpiFallback.Switch(Project, link.PortName), saved, connector, cancellationToken);
        StatusLine.Show(
            $"{station.Name}: reading {link.PortName} over PPI at {PpiFallback.DescribeBaud(PpiFallback.BaudFor(link))} while its handler does not answer; "
            + "values are read and written, STOP and handler checks are off; Line > Back to Freeport returns");
    }

    /// <summary>Ends <see cref="ReadOverPpiAsync"/>: the project's own links again, reconnected if the line was connected.</summary>
    public async Task BackToFreeportAsync(CancellationToken cancellationToken = default)
    {
        if (!IsReadingOverPpi)
        {
            return;
        }

        await RelinkAsync(SavedProject, saved: null, IsConnected ? _connector : null, cancellationToken);
        StatusLine.Show($"Back to Freeport: {string.Join(", ", Project.Stations.Select(s => $"{s.Name} {s.Link.LineText}"))}");
    }

    /// <summary>Disconnects, takes <paramref name="project"/> (same stations, other links) without an edit, and reconnects.</summary>
    private async Task RelinkAsync(PanelProject project, PanelProject? saved, ILineConnector? connector, CancellationToken cancellationToken)
    {
        await DisconnectAsync();
        await _line.EditAsync(project);
        _freeportLinks = saved;
        OnPropertyChanged(nameof(Project));
        OnPropertyChanged(nameof(IsReadingOverPpi));
        ResetStations();
        if (connector is not null)
        {
            await ConnectAsync(connector, cancellationToken);
        }
    }
}
