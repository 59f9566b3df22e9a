using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Session;

/// <summary>One station as the status bar and the Diagnostics window show it: health, last error, identity, link counters.</summary>
public sealed partial class StationStatusViewModel(ProjectStation station) : ObservableObject
{
    private bool _hasAnswered;
    private bool _handlerOutdated;
    private bool _lineOpen;

    public ProjectStation Station { get; } = station;

    public string Name => Station.Name;

    public Station Address => Station.Address;

    public string PortText => $"{Station.Link.PortName} {Station.Link.LineText}{(IsPpi ? " PPI" : string.Empty)}";

    /// <summary>The station's bus speaks PPI: no handler, no IDENTIFY; what PPI tells is <see cref="PpiIdentity"/>.</summary>
    public bool IsPpi => Station.Link.Protocol == LinkProtocol.Ppi;

    /// <summary>What the last PPI identify read (SMB6, SM0.7, scan times) on a PPI bus; null before one answered.</summary>
    [ObservableProperty]
    public partial PpiIdentity? PpiIdentity { get; private set; }

    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(HealthText))]
    [NotifyPropertyChangedFor(nameof(StopAvailable))]
    public partial StationHealth Health { get; private set; }

    /// <summary>The latest failure or refusal, kept after recovery so it can still be read.</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(HealthText))]
    public partial string? LastError { get; private set; }

    [ObservableProperty]
    public partial LinkStatistics Statistics { get; private set; } = LinkStatistics.Empty;

    /// <summary>For a silent station resting while others on its bus answer, when the panel tries it next; else null.</summary>
    [ObservableProperty]
    public partial DateTimeOffset? NextTryAt { get; private set; }

    /// <summary>The station's IDENTIFY reply; null until it answered one.</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(CpuMismatch))]
    [NotifyPropertyChangedFor(nameof(StopAvailable))]
    public partial StationIdentity? Identity { get; private set; }

    /// <summary>The PLC reports another CPU than the project's: addresses were checked against the wrong sizes.</summary>
    public bool CpuMismatch => Identity?.Contradicts(Station.Cpu) == true;

    public string HealthText => Health switch
    {
        StationHealth.Online => "online",
        StationHealth.Offline => "offline: " + (LastError ?? "no reply"),
        StationHealth.Stopped => "no answer: PLC in STOP, mode switch at TERM, or off the bus",
        StationHealth.HandlerMismatch =>
            $"handler protocol version {Identity?.ProtocolVersion} is not the panel's {StationIdentity.PanelProtocol}: generate and download the PLC code again",
        StationHealth.StoppedByPanel => "stopped by the panel: the port speaks PPI until someone sets RUN",
        StationHealth.HandlerOutdated => "handler of an older protocol (the panel speaks v3): regenerate the PLC code (File > Generate PLC code) and download it",
        StationHealth.Unknown => _lineOpen ? "not read yet" : "not connected",
    };

    /// <summary>
    /// Stop may be offered: the project allows STOP for this station and its IDENTIFY reported FEATURES bit 0, and it is
    /// not already stopped. The session adds its own conditions (connected, not read-only).
    /// </summary>
    public bool StopAvailable => Station.AllowStop && Identity is { StopEnabled: true } && Health != StationHealth.StoppedByPanel;

    /// <summary>Why the last IDENTIFY brought no identity; null after one that did.</summary>
    [ObservableProperty]
    public partial string? IdentifyError { get; private set; }

    /// <summary>
    /// Takes the line's state of the station: its polling status (null when not connected), link counters, the last
    /// answered IDENTIFY and what the last IDENTIFY brought. The identity of an earlier answer is kept while none comes
    /// (a later IDENTIFY that failed, a disconnect).
    /// </summary>
    /// <summary>Takes what a PPI identify brought: the identity is kept while a later one fails.</summary>
    internal void NotePpiIdentify(PpiIdentifyOutcome outcome)
    {
        ArgumentNullException.ThrowIfNull(outcome);
        PpiIdentity = outcome.Identity ?? PpiIdentity;
        IdentifyError = outcome.Identity is null ? $"PPI identify: {outcome.Error}" : null;
    }

    internal void Update(StationStatus? status, LinkStatistics statistics, IdentifyResponse? identity = null, LinkReply? lastIdentify = null)
    {
        Statistics = statistics;
        NextTryAt = status?.NextTryAt;
        // No status: the line is closed. A status still Unknown: the line is open and the station has not answered yet.
        if (_lineOpen != status is not null)
        {
            _lineOpen = status is not null;
            OnPropertyChanged(nameof(HealthText));
        }

        if (identity is not null)
        {
            _hasAnswered = true;
            Identity = StationIdentity.From(identity);
        }

        if (lastIdentify is not null)
        {
            var failure = lastIdentify.Failure;
            _handlerOutdated = failure?.Kind == PlcErrorKind.HandlerOutdated;
            IdentifyError = lastIdentify.Response switch
            {
                IdentifyResponse => null,
                ErrorResponse refused => $"IDENTIFY refused: {refused.Error}",
                null => $"IDENTIFY: {failure!.Kind}: {failure.Message}",
                _ => "IDENTIFY: unexpected reply",
            };
        }

        if (status is null)
        {
            Health = StationHealth.Unknown;
            return;
        }

        LastError = status.LastError;
        _hasAnswered |= status.State == StationState.Online;
        Health = Judge(status);
    }

    private StationHealth Judge(StationStatus status)
    {
        if (Identity is { ProtocolMatches: false })
        {
            return StationHealth.HandlerMismatch;
        }

        if (_handlerOutdated && status.State != StationState.Online)
        {
            return StationHealth.HandlerOutdated;
        }

        // StationTracker writes "{kind}: {message}"; a missing port is offline whatever the station did before.
        var portGone = status.LastError?.StartsWith(nameof(PlcErrorKind.PortUnavailable), StringComparison.Ordinal) == true;
        return status.State switch
        {
            StationState.Online => StationHealth.Online,
            StationState.StoppedByPanel => StationHealth.StoppedByPanel,
            // Over PPI a CPU answers in STOP too: its silence is not a STOP.
            StationState.Offline when !portGone && _hasAnswered && !IsPpi => StationHealth.Stopped,
            StationState.Offline => StationHealth.Offline,
            StationState.Unknown => StationHealth.Unknown,
        };
    }
}
