using System.Collections.ObjectModel;
using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using OperatorPanel.ViewModels.Services;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// The open project and its <see cref="ProjectLine"/>. Every window (Inputs, Outputs, Memory, Diagnostics, Alarms) reads
/// the project and its changes from here, and values from <see cref="Values"/>: the line hands each batch of changes to
/// <see cref="IUiDispatcher"/>, so every value callback runs on the UI thread. Writes go through <see cref="WriteAsync"/>,
/// which the engine logs with old and new value (Core/Writes/WriteLog), so nothing here logs them again.
/// </summary>
public sealed partial class PanelSession : ObservableObject
{
    private readonly IUiDispatcher _dispatcher;
    private readonly TimeProvider _time;
    private readonly ProjectLine _line;

    public PanelSession(PanelProject project, IUiDispatcher dispatcher, TimeProvider? time = null, ILogger? logger = null)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(dispatcher);
        _dispatcher = dispatcher;
        _time = time ?? TimeProvider.System;
        var options = new ProjectLineOptions
        {
            LinkOptionsFor = serial => LinkOptionsFor(serial),
            // One post per batch: the rows first, then the status bar, which the same cycle may have changed.
            Deliver = work => _dispatcher.Post(() =>
            {
                work();
                UpdateStations();
            }),
        };
        _line = new ProjectLine(project, options, _time, (logger ?? Logger.None).ForContext<PanelSession>());
        Project = project;
        Mode = project.Refresh.Mode;
        Stations = [.. project.Stations.Select(s => new StationStatusViewModel(s))];
    }

    /// <summary>
    /// The timing and retry rules of each bus's link; LinkOptions.For (the medium's defaults) unless the App sets a
    /// longer scan allowance for slow PLC programs. Set before connecting.
    /// </summary>
    public Func<SerialSettings, LinkOptions> LinkOptionsFor { get; init; } = serial => LinkOptions.For(serial);

    /// <summary>The project is replaced, edited or saved. Raised on the UI thread.</summary>
    public event EventHandler<ProjectChangedEventArgs>? ProjectChanged;

    /// <summary>Where the session hands work to the UI thread; the shell's history reports problems through it too.</summary>
    public IUiDispatcher Dispatcher => _dispatcher;

    /// <summary>The line's values: a row subscribes to its address and hears every change on the UI thread.</summary>
    public ILineValues Values => _line;

    [ObservableProperty]
    public partial PanelProject Project { get; private set; }

    public ObservableCollection<StationStatusViewModel> Stations { get; }

    public StatusLine StatusLine { get; } = new();

    /// <summary>The operator's refresh mode; switches the running engines at once. Not saved in the project.</summary>
    [ObservableProperty]
    public partial RefreshMode Mode { get; set; }

    /// <summary>No write reaches a PLC while set: every writing command is disabled, and the session refuses too.</summary>
    [ObservableProperty]
    public partial bool IsReadOnly { get; set; }

    /// <summary>Where each write and STOP is recorded, intent before it is sent and outcome after (the project's history).</summary>
    public IAuditTrail Audit { get; set; } = NoAuditTrail.Instance;

    /// <summary>Who works the panel, as the audit and the alarm journal record it: the Windows user.</summary>
    public string User { get; init; } = Environment.UserName;

    /// <summary>
    /// Writes through the station's engine; the outcome is the PLC's read-back, never the request. The audit gets the
    /// intent (with the last polled value) before the write is queued, and the outcome after.
    /// </summary>
    public async Task<WriteOutcome> WriteAsync(WriteRequest request, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        if (IsReadOnly)
        {
            return new WriteOutcome.Failed($"{request.Address}: read-only mode, nothing written", WriteFailureKind.InvalidRequest);
        }

        _line.TryGetValue(request.Station, request.Address, out var old);
        var intent = AuditEntries.WriteIntent(AuditEntries.NextOperation(), _time.GetUtcNow(), request, old.Raw, User);
        Audit.Record(intent);
        WriteOutcome outcome;
        try
        {
            outcome = await _line.WriteAsync(request, cancellationToken);
        }
        catch (OperationCanceledException)
        {
            Audit.Record(AuditEntries.Withdrawn(intent, _time.GetUtcNow()));
            throw;
        }

        Audit.Record(AuditEntries.WriteResult(intent, _time.GetUtcNow(), outcome));
        UpdateStations();
        return outcome;
    }

    /// <summary>The station's polling status (no exchange: the engine's own state); null when not connected.</summary>
    public StationStatus? StatusOf(Station station) => _line.StatusOf(station);

    /// <summary>Takes another project (new, opened, demo). Disconnect first: the old line belongs to the old project.</summary>
    public void Load(PanelProject project)
    {
        _line.Load(project);
        Project = project;
        Mode = project.Refresh.Mode;
        ResetStations();
        ProjectChanged?.Invoke(this, new ProjectChangedEventArgs(project, ProjectChangeKind.Replaced));
    }

    /// <summary>Tells every window the project was saved (the shell clears its dirty mark).</summary>
    public void MarkSaved() => ProjectChanged?.Invoke(this, new ProjectChangedEventArgs(Project, ProjectChangeKind.Saved));

    /// <summary>Reads every station's status and link counters into <see cref="Stations"/>; call on the UI thread.</summary>
    public void UpdateStations()
    {
        foreach (var station in Stations)
        {
            station.Update(_line.StatusOf(station.Address), _line.StatisticsFor(station.Address));
        }
    }

    partial void OnModeChanged(RefreshMode value) => _line.Mode = value;

    private void ResetStations()
    {
        Stations.Clear();
        foreach (var station in Project.Stations)
        {
            Stations.Add(new StationStatusViewModel(station));
        }
    }
}
