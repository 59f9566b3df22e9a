using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Session;

/// <summary>IDENTIFY for the Diagnostics window and the status bar: which CPU and handler each station really runs.</summary>
public sealed partial class PanelSession
{
    /// <summary>Sends IDENTIFY to every station (beside the polling, one request on the wire at a time) for Diagnostics.</summary>
    public async Task IdentifyAsync(CancellationToken cancellationToken = default)
    {
        foreach (var view in IsConnected ? Stations.ToList() : [])
        {
            try
            {
                var reply = await _line.IdentifyAsync(view.Address, cancellationToken);
                view.RecordIdentify(reply as IdentifyResponse, reply is ErrorResponse refused ? $"IDENTIFY refused: {refused.Error}" : null);
            }
            catch (PlcCommunicationException exception)
            {
                view.RecordIdentify(null, $"IDENTIFY: {exception.Kind}: {exception.Message}", exception.Kind == PlcErrorKind.HandlerProtocolV1);
            }
        }

        UpdateStations();
        foreach (var view in Stations.Where(s => s.CpuMismatch))
        {
            StatusLine.ShowError($"{view.Name}: the PLC reports {view.Identity!.CpuText}, the project says {view.Station.Cpu.DisplayName}");
        }
    }
}
