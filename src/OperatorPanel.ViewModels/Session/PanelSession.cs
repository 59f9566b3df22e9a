using System.Collections.ObjectModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Writes;
using OperatorPanel.ViewModels.Mvvm;
using OperatorPanel.ViewModels.Services;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// The open project and, while connected, its line: per port a <see cref="PlcLink"/> and a <see cref="PollingEngine"/>.
/// Every window (Inputs, Outputs, Memory, Diagnostics, Alarms) reads values and project changes from here, on the UI
/// thread: engine batches are marshalled through <see cref="IUiDispatcher"/>. Writes go through <see cref="WriteAsync"/>,
/// which the engine logs with old and new value (Core/Writes/WriteLog), so nothing here logs them again.
/// </summary>
public sealed partial class PanelSession : ObservableObject
{
    private readonly IUiDispatcher _dispatcher;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;
    private PanelProject _project;
    private RefreshMode _mode;
    private bool _isReadOnly;

    public PanelSession(PanelProject project, IUiDispatcher dispatcher, TimeProvider? time = null, ILogger? logger = null)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(dispatcher);
        _dispatcher = dispatcher;
        _time = time ?? TimeProvider.System;
        _logger = (logger ?? Logger.None).ForContext<PanelSession>();
        _project = project;
        _mode = project.Refresh.Mode;
        Stations = [.. project.Stations.Select(s => new StationStatusViewModel(s))];
    }

    /// <summary>
    /// The timing and retry rules of each bus's link; LinkOptions.For (the medium's defaults) unless the App sets a
    /// longer scan allowance for slow PLC programs. Set before connecting.
    /// </summary>
    public Func<Core.Transport.SerialSettings, LinkOptions> LinkOptionsFor { get; init; } = serial => LinkOptions.For(serial);

    /// <summary>The project is replaced, edited or saved. Raised on the UI thread.</summary>
    public event EventHandler<ProjectChangedEventArgs>? ProjectChanged;

    /// <summary>Values changed (a poll cycle, a write's read-back) or must all be re-read. Raised on the UI thread.</summary>
    public event EventHandler<ValuesChangedEventArgs>? ValuesChanged;

    public PanelProject Project
    {
        get => _project;
        private set => SetProperty(ref _project, value);
    }

    public ObservableCollection<StationStatusViewModel> Stations { get; }

    public StatusLine StatusLine { get; } = new();

    /// <summary>The operator's refresh mode; switches the running engines at once. Not saved in the project.</summary>
    public RefreshMode Mode
    {
        get => _mode;
        set
        {
            if (SetProperty(ref _mode, value))
            {
                _runs.ForEach(r => r.Engine.Mode = value);
            }
        }
    }

    /// <summary>No write reaches a PLC while set: every writing command is disabled, and the session refuses too.</summary>
    public bool IsReadOnly
    {
        get => _isReadOnly;
        set => SetProperty(ref _isReadOnly, value);
    }

    /// <summary>The latest value of an address the project watches; false when not connected or not watched.</summary>
    public bool TryGetValue(Station station, PlcAddress address, out PolledValue value)
    {
        foreach (var run in _runs)
        {
            if (run.Bus.StationAt(station) is not null)
            {
                return run.Engine.TryGetValue(station, address, out value);
            }
        }

        value = PolledValue.NotRead(_time.GetUtcNow());
        return false;
    }

    /// <summary>Writes through the station's engine; the outcome is the PLC's read-back, never the request.</summary>
    public async Task<WriteOutcome> WriteAsync(WriteRequest request, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        if (IsReadOnly)
        {
            return new WriteOutcome.Failed($"{request.Address}: read-only mode, nothing written", WriteFailureKind.InvalidRequest);
        }

        var run = _runs.FirstOrDefault(r => r.Bus.StationAt(request.Station) is not null);
        if (run is null)
        {
            return new WriteOutcome.Failed($"{request.Address}: not connected, nothing written", WriteFailureKind.InvalidRequest);
        }

        var outcome = await run.Engine.WriteAsync(request, cancellationToken);
        UpdateStations();
        return outcome;
    }

    /// <summary>Takes another project (new, opened, demo). Disconnect first: the old line belongs to the old project.</summary>
    public void Load(PanelProject project)
    {
        ArgumentNullException.ThrowIfNull(project);
        if (IsConnected)
        {
            throw new InvalidOperationException("disconnect before loading another project");
        }

        Project = project;
        Mode = project.Refresh.Mode;
        ResetStations();
        ProjectChanged?.Invoke(this, new ProjectChangedEventArgs(project, ProjectChangeKind.Replaced));
        ValuesChanged?.Invoke(this, new ValuesChangedEventArgs([], reset: true));
    }

    /// <summary>Tells every window the project was saved (the shell clears its dirty mark).</summary>
    public void MarkSaved() => ProjectChanged?.Invoke(this, new ProjectChangedEventArgs(Project, ProjectChangeKind.Saved));

    /// <summary>Reads every station's status and link counters into <see cref="Stations"/>; call on the UI thread.</summary>
    public void UpdateStations()
    {
        foreach (var station in Stations)
        {
            var run = _runs.FirstOrDefault(r => r.Bus.StationAt(station.Address) is not null);
            station.Update(run?.Engine.GetStationStatus(station.Address), run?.Link.StatisticsFor(station.Address) ?? Core.Link.LinkStatistics.Empty);
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

    private void OnEngineChanges(IReadOnlyList<ValueChange> changes) => _dispatcher.Post(() =>
    {
        ValuesChanged?.Invoke(this, new ValuesChangedEventArgs(changes, reset: false));
        UpdateStations();
    });
}
