using OperatorPanel.Core.Line;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Session;

/// <summary>Connecting (and identifying every station), disconnecting, refreshing, and following project edits while connected.</summary>
public sealed partial class PanelSession : IAsyncDisposable
{
    private ILineConnector? _connector;

    /// <summary>The line is connected: its ports are open and its buses poll.</summary>
    public bool IsConnected => _line.IsConnected;

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
        OnPropertyChanged(nameof(IsConnected));
        // "Polling", not "connected": whether each station answers is the station's own state beside this line.
        StatusLine.Show($"Polling {string.Join(", ", Project.Stations.Select(s => s.Name))} on {string.Join(", ", _line.PortNames)}");
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

        await _line.DisconnectAsync();
        OnPropertyChanged(nameof(IsConnected));
        StatusLine.Show("Disconnected");
    }

    /// <summary>
    /// Sends IDENTIFY to every station through its bus's queue (beside the polling, one request on the wire at a time),
    /// for Diagnostics and the status bar: which CPU and handler each station really runs. The line keeps what each reply
    /// said; the station views read it at the line's StateChanged.
    /// </summary>
    public async Task IdentifyAsync(CancellationToken cancellationToken = default)
    {
        foreach (var view in IsConnected ? Stations.ToList() : [])
        {
            if (view.IsPpi)
            {
                // No handler on a PPI bus: what PPI tells about the CPU instead (docs/ppi.md section 9).
                view.NotePpiIdentify(await _line.IdentifyPpiAsync(view.Address, cancellationToken));
                continue;
            }

            await _line.IdentifyAsync(view.Address, cancellationToken);
        }

        foreach (var view in Stations.Where(s => s.CpuMismatch))
        {
            StatusLine.ShowError($"{view.Name}: the PLC reports {view.Identity!.CpuText}, the project says {view.Station.Cpu.DisplayName}");
        }
    }

    /// <summary>
    /// One full cycle of every bus: in triggered mode the only way values change; in continuous mode the next regular cycle.
    /// </summary>
    public Task RefreshNowAsync(CancellationToken cancellationToken = default) => _line.RefreshAsync(cancellationToken);

    /// <summary>
    /// Takes an edited version of the same project (memory cells added, removed, moved, reformatted). While connected,
    /// each bus whose watch list changed polls its new plan on its open port; a changed set of ports or stations reconnects.
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

        var mode = Mode;
        await _line.EditAsync(edited);
        OnProjectReplaced(mode);
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

    public async ValueTask DisposeAsync()
    {
        await DisconnectAsync();
        StatusLine.Dispose();
    }
}
