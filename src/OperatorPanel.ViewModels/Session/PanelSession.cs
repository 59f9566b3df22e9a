using System.Collections.ObjectModel;
using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using OperatorPanel.ViewModels.Services;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// The open project and its <see cref="ProjectLine"/>, which owns the project, the refresh mode and the connection: the
/// session exposes them and raises their changes, it keeps no copy. Every window (Inputs, Outputs, Memory, Diagnostics,
/// Alarms) reads the project and its changes from here, and values from <see cref="Values"/>: the line hands each batch
/// to <see cref="IUiDispatcher"/>, so every value callback runs on the UI thread, and ends it with
/// <see cref="ProjectLine.StateChanged"/>, the one trigger of the status bar (<see cref="Stations"/>). Writes go through
/// <see cref="WriteAsync"/>, which the bus logs with old and new value (Core/Writes/WriteLog), so nothing here logs them again.
/// </summary>
public sealed partial class PanelSession : ObservableObject
{
    private readonly IUiDispatcher _dispatcher;
    private readonly TimeProvider _time;
    private readonly ProjectLine _line;
    private StationStatusViewModel? _silentFreeportStation;

    /// <param name="project">The project to open.</param>
    /// <param name="dispatcher">Where value callbacks run (the UI thread).</param>
    /// <param name="time">The clock.</param>
    /// <param name="logger">The panel's log.</param>
    /// <param name="journal">
    /// The write journal (WriteJournal.In the panel's log folder, shared with opanel): every write and STOP goes on record
    /// before it is sent, and connecting settles the writes an earlier program left cut short. Null keeps no journal (tests).
    /// </param>
    public PanelSession(PanelProject project, IUiDispatcher dispatcher, TimeProvider? time = null, ILogger? logger = null, WriteJournal? journal = null)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(dispatcher);
        _dispatcher = dispatcher;
        _time = time ?? TimeProvider.System;
        var options = new ProjectLineOptions
        {
            LinkOptionsFor = serial => LinkOptionsFor(serial),
            Deliver = dispatcher.Post,
            Journal = journal,
            Audit = AuditTrail.Combine(journal ?? AuditTrail.None, [new HistoryTrail(this)], logger),
        };
        _line = new ProjectLine(project, options, _time, (logger ?? Logger.None).ForContext<PanelSession>());
        _line.StateChanged += (_, _) => UpdateStations();
        Stations = [.. project.Stations.Select(s => new StationStatusViewModel(s))];
        StatusLine = new StatusLine(time ?? TimeProvider.System, dispatcher);
    }

    /// <summary>
    /// The timing and retry rules of each bus's link; V3LinkOptions.For (protocol v3, the medium's defaults) unless the
    /// App sets a longer scan allowance for slow PLC programs. Set before connecting.
    /// </summary>
    public Func<SerialSettings, LinkOptions> LinkOptionsFor { get; init; } = serial => V3LinkOptions.For(serial);

    /// <summary>The project is replaced, edited or saved. Raised on the UI thread.</summary>
    public event EventHandler<ProjectChangedEventArgs>? ProjectChanged;

    /// <summary>Where the session hands work to the UI thread; the shell's history reports problems through it too.</summary>
    public IUiDispatcher Dispatcher => _dispatcher;

    /// <summary>The line's values: a row subscribes to its address and hears every change on the UI thread.</summary>
    public ILineValues Values => _line;

    /// <summary>The line's project.</summary>
    public PanelProject Project => _line.Project;

    public ObservableCollection<StationStatusViewModel> Stations { get; }

    public StatusLine StatusLine { get; }

    /// <summary>The operator's refresh mode, the line's: switches the running buses at once. Not saved in the project.</summary>
    public RefreshMode Mode
    {
        get => _line.Mode;
        set
        {
            if (_line.Mode != value)
            {
                _line.Mode = value;
                OnPropertyChanged();
                OnPropertyChanged(nameof(IsContinuous));
            }
        }
    }

    /// <summary><see cref="Mode"/> as the View menu's check mark: continuous (true) or triggered.</summary>
    public bool IsContinuous
    {
        get => Mode == RefreshMode.Continuous;
        set => Mode = value ? RefreshMode.Continuous : RefreshMode.OnDemand;
    }

    /// <summary>No write reaches a PLC while set: every writing command is disabled, and the session refuses too.</summary>
    [ObservableProperty]
    public partial bool IsReadOnly { get; set; }

    /// <summary>
    /// Writes through the station's bus; the outcome is the PLC's read-back, never the request. The bus puts the intent on
    /// record (the journal, then <see cref="Audit"/>) before it sends the write, and the outcome after.
    /// </summary>
    public async Task<WriteOutcome> WriteAsync(WriteRequest request, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        if (IsReadOnly)
        {
            return new WriteOutcome.Failed($"{request.Address}: read-only mode, nothing written", WriteFailureKind.InvalidRequest);
        }

        return await _line.WriteAsync(request, cancellationToken);
    }

    /// <summary>The station's polling status (no exchange: the engine's own state); null when not connected.</summary>
    public StationStatus? StatusOf(Station station) => _line.StatusOf(station);

    /// <summary>Takes another project (new, opened, demo). Disconnect first: the old line belongs to the old project.</summary>
    public void Load(PanelProject project)
    {
        var mode = Mode;
        _line.Load(project);
        _freeportLinks = null;
        OnPropertyChanged(nameof(IsReadingOverPpi));
        OnProjectReplaced(mode);
        ResetStations();
        ProjectChanged?.Invoke(this, new ProjectChangedEventArgs(project, ProjectChangeKind.Replaced));
    }

    /// <summary>Tells every window the project was saved (the shell clears its dirty mark).</summary>
    public void MarkSaved() => ProjectChanged?.Invoke(this, new ProjectChangedEventArgs(Project, ProjectChangeKind.Saved));

    /// <summary>Reads every station's status, link counters and IDENTIFY from the line into <see cref="Stations"/>: on the UI thread, at each StateChanged.</summary>
    private void UpdateStations()
    {
        foreach (var station in Stations)
        {
            var address = station.Address;
            station.Update(_line.StatusOf(address), _line.StatisticsFor(address), _line.IdentityOf(address), _line.LastIdentifyOf(address));
        }

        // The shell offers "Read over PPI" while a Freeport station is silent: it hears when that changes.
        if (SilentFreeportStation != _silentFreeportStation)
        {
            _silentFreeportStation = SilentFreeportStation;
            OnPropertyChanged(nameof(SilentFreeportStation));
        }
    }

    /// <summary>The line took another project and its refresh mode: the views hear of both.</summary>
    private void OnProjectReplaced(RefreshMode modeBefore)
    {
        OnPropertyChanged(nameof(Project));
        if (Mode != modeBefore)
        {
            OnPropertyChanged(nameof(Mode));
            OnPropertyChanged(nameof(IsContinuous));
        }
    }

    private void ResetStations()
    {
        Stations.Clear();
        foreach (var station in Project.Stations)
        {
            Stations.Add(new StationStatusViewModel(station));
        }
    }
}
