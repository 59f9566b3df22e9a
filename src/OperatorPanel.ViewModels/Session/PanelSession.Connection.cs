using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Session;

/// <summary>Connecting, disconnecting, refreshing, and following project edits while connected.</summary>
public sealed partial class PanelSession : IAsyncDisposable
{
    /// <summary>Link counters change every cycle without any value changing: the status bar samples them this often.</summary>
    private static readonly TimeSpan StatusPeriod = TimeSpan.FromSeconds(1);

    private ILineConnector? _connector;
    private ITimer? _statusTimer;

    [ObservableProperty]
    public partial bool IsConnected { get; private set; }

    /// <summary>Opens the project's ports through <paramref name="connector"/>, starts polling and identifies every station.</summary>
    public async Task ConnectAsync(ILineConnector connector, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(connector);
        if (IsConnected)
        {
            return;
        }

        _connector = connector;
        await _line.ConnectAsync(connector, cancellationToken);
        IsConnected = true;
        _statusTimer = _time.CreateTimer(_ => _dispatcher.Post(UpdateStations), null, StatusPeriod, StatusPeriod);
        StatusLine.Show($"Connected to {Project.Stations.Length} station(s) on {string.Join(", ", _line.PortNames)}");
        if (_line.ResolvedAtConnect is [var first, ..] cutShort)
        {
            // An earlier program was killed with a write on the wire: the operator learns what it did (the log has each).
            StatusLine.ShowError(cutShort.Count == 1 ? first.Describe() : $"{cutShort.Count} writes cut short earlier were settled at start (see the log); the first: {first.Describe()}");
        }

        await IdentifyAsync(cancellationToken);
    }

    public async Task DisconnectAsync()
    {
        if (!IsConnected)
        {
            return;
        }

        _statusTimer?.Dispose();
        _statusTimer = null;
        await _line.DisconnectAsync();
        IsConnected = false;
        UpdateStations();
        StatusLine.Show("Disconnected");
    }

    /// <summary>
    /// One full cycle of every bus: in triggered mode the only way values change; in continuous mode the next regular cycle.
    /// </summary>
    public async Task RefreshNowAsync(CancellationToken cancellationToken = default)
    {
        await _line.RefreshAsync(cancellationToken);
        UpdateStations();
    }

    /// <summary>
    /// Takes an edited version of the same project (memory cells added, removed, moved, reformatted). While connected,
    /// each bus whose watch list changed gets a new engine on its open link; a changed set of ports or stations reconnects.
    /// </summary>
    public async Task EditProjectAsync(PanelProject edited)
    {
        ArgumentNullException.ThrowIfNull(edited);
        var sameStations = ProjectLine.SameStations(Project, edited);
        var reconnect = IsConnected && !sameStations ? _connector : null;
        if (reconnect is not null)
        {
            await DisconnectAsync();
        }

        await _line.EditAsync(edited);
        Project = edited;
        if (!sameStations)
        {
            ResetStations();
        }

        if (reconnect is not null)
        {
            await ConnectAsync(reconnect);
        }

        ProjectChanged?.Invoke(this, new ProjectChangedEventArgs(edited, ProjectChangeKind.Edited));
    }

    public async ValueTask DisposeAsync() => await DisconnectAsync();
}
