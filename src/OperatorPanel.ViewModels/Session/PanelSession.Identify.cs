using OperatorPanel.Core.Link;
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
            switch (await _line.IdentifyAsync(view.Address, cancellationToken))
            {
                case LinkReply.Answered { Response: var reply }:
                    view.RecordIdentify(reply as IdentifyResponse, reply is ErrorResponse refused ? $"IDENTIFY refused: {refused.Error}" : null);
                    break;
                case LinkReply.Failed { Failure: var failure }:
                    view.RecordIdentify(null, $"IDENTIFY: {failure.Kind}: {failure.Message}", failure.Kind == PlcErrorKind.HandlerProtocolV1);
                    break;
            }
        }

        UpdateStations();
        foreach (var view in Stations.Where(s => s.CpuMismatch))
        {
            StatusLine.ShowError($"{view.Name}: the PLC reports {view.Identity!.CpuText}, the project says {view.Station.Cpu.DisplayName}");
        }
    }
}
