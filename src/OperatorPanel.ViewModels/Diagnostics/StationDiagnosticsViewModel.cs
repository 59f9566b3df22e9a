using System.ComponentModel;
using System.Globalization;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Diagnostics;

/// <summary>
/// One station in the Diagnostics window: the CPU the PLC reports (IDENTIFY) beside the project's, RUN/STOP, the scan
/// times SMW22/SMW24/SMW26 (seed 002 Table C-9) and the link counters. Follows its <see cref="StationStatusViewModel"/>.
/// Its Stop command puts the PLC into STOP after the operator confirms.
/// </summary>
public sealed partial class StationDiagnosticsViewModel : ObservableObject
{
    private readonly PanelSession _session;
    private readonly IDialogService _dialogs;

    public StationDiagnosticsViewModel(StationStatusViewModel status, PanelSession session, IDialogService dialogs)
    {
        ArgumentNullException.ThrowIfNull(status);
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(dialogs);
        Status = status;
        (_session, _dialogs) = (session, dialogs);
        status.PropertyChanged += OnStatusChanged;
    }

    public StationStatusViewModel Status { get; }

    public string Name => Status.Name;

    public string StationText => Status.Address.ToString();

    public string ProjectCpuText => Status.Station.Cpu.DisplayName;

    public string PlcCpuText => Status.PpiIdentity is { } ppi
        ? $"SMB6 16#{ppi.Smb6:X2} (read over PPI)"
        : Status.Identity?.CpuText ?? Status.IdentifyError ?? "not identified yet";

    /// <summary>
    /// How the panel reaches the station: "COM3 9600 8N1, cable, Freeport handler" or "COM3 19200 8E1, cable, PPI, no
    /// handler" (port, baud rate, data bits, parity, stop bits, medium, protocol).
    /// </summary>
    public string LinkText => $"{Status.Station.Link.PortName} {Status.Station.Link.LineText}, "
        + (Status.Station.Link.Kind == Core.Transport.LinkKind.RadioModule ? "radio module" : "cable")
        + (Status.IsPpi ? ", PPI, no handler" : ", Freeport handler");

    public bool CpuMismatch => Status.CpuMismatch;

    public string CpuMismatchText => CpuMismatch
        ? $"The PLC reports {Status.Identity!.CpuText}, the project is set up for {ProjectCpuText}: addresses were checked against the wrong CPU."
        : string.Empty;

    /// <summary>Why a silent station is not tried every cycle, and when it is tried next (local time); empty otherwise.</summary>
    public string RetryText => Status.NextTryAt is { } next
        ? $"Silent while other stations on its bus answer: tried again at {next.ToLocalTime():HH:mm:ss}, not every cycle, so it does not slow their refresh."
        : string.Empty;

    /// <summary>SMB6 as the manual writes it, e.g. 16#20.</summary>
    public string Smb6Text => (Status.Identity?.Smb6 ?? Status.PpiIdentity?.Smb6) is { } smb6 ? "16#" + smb6.ToString("X2", CultureInfo.InvariantCulture) : "-";

    public string HandlerText => Status.IsPpi
        ? "none needed: the bus speaks PPI"
        : Status.Identity is { } id
        ? $"protocol {id.ProtocolVersion}, handler revision {id.HandlerRevision}{(id.ProtocolMatches ? string.Empty : " (the panel speaks protocol " + StationIdentity.PanelProtocol + ")")}"
            + (id.V3 is { } v3 ? $", {(v3.HasList ? "full" : "compact")}" : string.Empty)
        : "-";

    /// <summary>
    /// The v3 IDENTIFY's shape fields: FEATURES, LIST_ITEMS and LIST_BYTES, MAX_REQUEST, END_TIMEOUT_MS, the handler's
    /// V bytes (docs/protocol.md section 2, 01 IDENTIFY); "-" before one answered.
    /// </summary>
    public string HandlerShapeText => Status.Identity?.V3 is { } v3
        ? $"FEATURES 16#{v3.Features:X2} ({(v3.HasList ? "list" : "no list")}{(v3.HasStop ? ", STOP" : string.Empty)}); "
            + (v3.HasList ? $"list of {v3.ListItems} items, {v3.ListBytes} bytes; " : "no list: read with READ; ")
            + $"requests up to {v3.MaxRequestBytes} bytes; END_TIMEOUT_MS {v3.EndTimeoutMs}; own V bytes VB{v3.VFirst}-VB{v3.VFirst + v3.VBytes - 1}"
        : "-";

    /// <summary>RUN when it answers (Freeport works only in RUN); STOP or TERM when it went silent after answering.</summary>
    public string RunStopText => Status.IsPpi ? PpiRunStopText : Status.Health switch
    {
        StationHealth.Online or StationHealth.HandlerMismatch => Status.Identity is { ModeSwitchRun: false } ? "RUN, mode switch at TERM" : "RUN",
        StationHealth.Stopped => "STOP or TERM (no Freeport reply)",
        StationHealth.StoppedByPanel => "STOP (by the panel)",
        StationHealth.HandlerOutdated => "RUN (handler of an older protocol)",
        StationHealth.Offline => "unknown (offline)",
        StationHealth.Unknown => "-",
    };

    /// <summary>Over PPI RUN or STOP cannot be read (docs/ppi.md section 9); the mode switch can (SM0.7).</summary>
    private string PpiRunStopText =>
        $"unknown over PPI{(Status.PpiIdentity is { } ppi ? $" (mode switch at {(ppi.SwitchAtRun ? "RUN" : "TERM")})" : string.Empty)}";

    public string ScanTimesText => Status.Identity is { } id
        ? $"last {id.LastScanMs} ms, min {id.MinScanMs} ms, max {id.MaxScanMs} ms"
        : Status.PpiIdentity is { } ppi ? $"last {ppi.LastScanMs} ms, min {ppi.MinScanMs} ms, max {ppi.MaxScanMs} ms" : "-";

    public string StatisticsText
    {
        get
        {
            var s = Status.Statistics;
            var average = s.RoundTripAverage is { } avg ? $"{avg.TotalMilliseconds:0} ms" : "-";
            return $"{s.Requests} requests, {s.Replies} replies, {s.Retries} retries, {s.Timeouts} timeouts, {s.CorruptFrames} corrupt, {s.NegativeReplies} refused; round trip {average}";
        }
    }

    public string HealthText => Status.HealthText;

    /// <summary>
    /// The session changed (connected, read-only): whether Stop may run depends on it. Called by the Diagnostics window,
    /// which outlives its rows, so a row never subscribes to the session itself.
    /// </summary>
    internal void OnSessionChanged()
    {
        StopCommand.NotifyCanExecuteChanged();
        ReadOverPpiCommand.NotifyCanExecuteChanged();
    }

    /// <summary>
    /// StopCommand: the project allows STOP for the station, its IDENTIFY reported FEATURES bit 0, the line is connected
    /// and not read-only. Always confirmed first (whatever "confirm writes" says): a STOP halts the line.
    /// </summary>
    [RelayCommand(CanExecute = nameof(CanStop))]
    private async Task StopAsync()
    {
        var question = $"Put {Name} ({Status.Address}) into STOP? Its program stops, so the line stops, and its port returns to PPI: "
            + "the panel cannot reach it until someone sets RUN (mode switch or Micro/WIN).";
        if (!await _dialogs.ConfirmAsync("Stop PLC", question, noByDefault: true))
        {
            return;
        }

        try
        {
            await _session.StopAsync(Status.Address);
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _session.StatusLine.ShowError($"{Name}: STOP failed: {exception.Message}");
        }
    }

    /// <summary>ReadOverPpiCommand: this Freeport station's handler fell silent; its bus reconnects over PPI (PanelSession.ReadOverPpiAsync).</summary>
    [RelayCommand(CanExecute = nameof(CanReadOverPpi))]
    private async Task ReadOverPpiAsync()
    {
        try
        {
            await _session.ReadOverPpiAsync(Status);
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _session.StatusLine.ShowError($"{Name}: not read over PPI: {exception.Message}");
        }
    }

    private bool CanReadOverPpi() => _session.IsConnected && PanelSession.CanReadOverPpi(Status);

    private bool CanStop() => Status.StopAvailable && _session.IsConnected && !_session.IsReadOnly;

    private void OnStatusChanged(object? sender, PropertyChangedEventArgs e)
    {
        OnPropertyChanged(string.Empty);
        StopCommand.NotifyCanExecuteChanged();
        ReadOverPpiCommand.NotifyCanExecuteChanged();
    }
}
