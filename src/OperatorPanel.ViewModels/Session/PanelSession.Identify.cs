namespace OperatorPanel.ViewModels.Session;

/// <summary>IDENTIFY for the Diagnostics window and the status bar: which CPU and handler each station really runs.</summary>
public sealed partial class PanelSession
{
    /// <summary>
    /// Sends IDENTIFY to every station through its bus's queue (beside the polling, one request on the wire at a time).
    /// The line keeps what each reply said; the status bar and Diagnostics read it at the line's StateChanged.
    /// </summary>
    public async Task IdentifyAsync(CancellationToken cancellationToken = default)
    {
        foreach (var view in IsConnected ? Stations.ToList() : [])
        {
            await _line.IdentifyAsync(view.Address, cancellationToken);
        }

        foreach (var view in Stations.Where(s => s.CpuMismatch))
        {
            StatusLine.ShowError($"{view.Name}: the PLC reports {view.Identity!.CpuText}, the project says {view.Station.Cpu.DisplayName}");
        }
    }
}
