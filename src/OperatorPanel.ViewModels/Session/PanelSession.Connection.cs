using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Session;

/// <summary>Connecting, disconnecting, refreshing, and following project edits while connected.</summary>
public sealed partial class PanelSession : IAsyncDisposable
{
    /// <summary>Link counters change every cycle without any value changing: the status bar samples them this often.</summary>
    private static readonly TimeSpan StatusPeriod = TimeSpan.FromSeconds(1);

    private readonly List<BusRun> _runs = [];
    private LineConnection? _connection;
    private ILineConnector? _connector;
    private ITimer? _statusTimer;
    private bool _isConnected;

    public bool IsConnected
    {
        get => _isConnected;
        private set => SetProperty(ref _isConnected, value);
    }

    /// <summary>Opens the project's ports through <paramref name="connector"/>, starts polling and identifies every station.</summary>
    public async Task ConnectAsync(ILineConnector connector, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(connector);
        if (IsConnected)
        {
            return;
        }

        _connector = connector;
        _connection = await connector.ConnectAsync(Project, cancellationToken);
        foreach (var bus in ProjectBus.Of(Project))
        {
            var link = new PlcLink(_connection.TransportFor(bus.Serial.PortName), LinkOptionsFor(bus.Serial), _time, _logger);
            _runs.Add(BusRun.Start(bus, link, Mode, Project.Refresh.MinimumPeriod, _time, _logger, OnEngineChanges));
        }

        IsConnected = true;
        _statusTimer = _time.CreateTimer(_ => _dispatcher.Post(UpdateStations), null, StatusPeriod, StatusPeriod);
        ValuesChanged?.Invoke(this, new ValuesChangedEventArgs([], reset: true));
        StatusLine.Show($"Connected to {Project.Stations.Length} station(s) on {string.Join(", ", _runs.Select(r => r.Link.PortName))}");
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
        foreach (var run in _runs)
        {
            await run.DisposeAsync();
        }

        // The connector's own parts (a demo line) stop before the ports close, or they would see an unplugged line.
        if (_connection is not null)
        {
            await _connection.DisposeAsync();
        }

        foreach (var run in _runs)
        {
            await run.Link.DisposeAsync();
        }

        _runs.Clear();
        _connection = null;
        IsConnected = false;
        UpdateStations();
        ValuesChanged?.Invoke(this, new ValuesChangedEventArgs([], reset: true));
        StatusLine.Show("Disconnected");
    }

    /// <summary>
    /// One full cycle of every bus: in triggered mode the only way values change; in continuous mode the next regular cycle.
    /// </summary>
    public async Task RefreshNowAsync(CancellationToken cancellationToken = default)
    {
        await Task.WhenAll(_runs.Select(r => r.Engine.RequestRefreshAsync(cancellationToken)));
        UpdateStations();
    }

    /// <summary>
    /// Takes an edited version of the same project (memory cells added, removed, moved, reformatted). While connected,
    /// each bus whose watch list changed gets a new engine on its open link; a changed set of ports or stations reconnects.
    /// </summary>
    public async Task EditProjectAsync(PanelProject edited)
    {
        ArgumentNullException.ThrowIfNull(edited);
        var sameStations = SameStations(Project, edited);
        Project = edited;
        if (!sameStations)
        {
            ResetStations();
        }

        if (IsConnected && _connector is { } connector)
        {
            if (sameStations)
            {
                await ReplaceEnginesForAsync(edited);
            }
            else
            {
                await DisconnectAsync();
                await ConnectAsync(connector);
            }
        }

        ProjectChanged?.Invoke(this, new ProjectChangedEventArgs(edited, ProjectChangeKind.Edited));
        ValuesChanged?.Invoke(this, new ValuesChangedEventArgs([], reset: true));
    }

    public async ValueTask DisposeAsync() => await DisconnectAsync();

    private async Task ReplaceEnginesForAsync(PanelProject edited)
    {
        var buses = ProjectBus.Of(edited);
        for (var i = 0; i < _runs.Count; i++)
        {
            var old = _runs[i];
            var bus = buses[i];
            if (!old.Bus.WatchedItems().SequenceEqual(bus.WatchedItems()))
            {
                // The old loop finishes its exchange first; the link and its statistics carry over.
                await old.DisposeAsync();
                _runs[i] = BusRun.Start(bus, old.Link, Mode, edited.Refresh.MinimumPeriod, _time, _logger, OnEngineChanges);
            }
        }
    }

    private static bool SameStations(PanelProject a, PanelProject b) =>
        a.Stations.Select(s => (s.Name, s.Address, s.Cpu, s.Link)).SequenceEqual(b.Stations.Select(s => (s.Name, s.Address, s.Cpu, s.Link)));
}
