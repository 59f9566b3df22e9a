using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Session;

/// <summary>IDENTIFY for the Diagnostics window and the status bar: which CPU and handler each station really runs.</summary>
public sealed partial class PanelSession
{
    private int _identifySequence;

    /// <summary>Sends IDENTIFY to every station (beside the polling, one request on the wire at a time) for Diagnostics.</summary>
    public async Task IdentifyAsync(CancellationToken cancellationToken = default)
    {
        foreach (var run in _runs.ToList())
        {
            foreach (var station in run.Bus.Stations)
            {
                var view = Stations.FirstOrDefault(s => s.Address == station.Address);
                var sequence = (byte)Interlocked.Increment(ref _identifySequence);
                try
                {
                    var reply = await run.Link.ExchangeAsync(new IdentifyRequest(station.Address, sequence), cancellationToken);
                    view?.RecordIdentify(reply as IdentifyResponse, reply is ErrorResponse refused ? $"IDENTIFY refused: {refused.Error}" : null);
                }
                catch (PlcCommunicationException exception)
                {
                    view?.RecordIdentify(null, $"IDENTIFY: {exception.Kind}: {exception.Message}");
                }
            }
        }

        UpdateStations();
        foreach (var view in Stations.Where(s => s.CpuMismatch))
        {
            StatusLine.ShowError($"{view.Name}: the PLC reports {view.Identity!.CpuText}, the project says {view.Station.Cpu.DisplayName}");
        }
    }
}
