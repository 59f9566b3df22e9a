using System.Collections.ObjectModel;
using System.ComponentModel;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Diagnostics;
using OperatorPanel.ViewModels.Docking;
using OperatorPanel.ViewModels.History;
using OperatorPanel.ViewModels.Inputs;
using OperatorPanel.ViewModels.Memory;
using OperatorPanel.ViewModels.Outputs;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Trends;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>
/// The main window: project file commands with dirty tracking, the line (connect, refresh mode, refresh now, demo,
/// read-only), the per-station status bar, the panes (with the Alarms pane and the alarm count), the project wizard
/// (File > New, Edit project) and Generate PLC code. Everything reads <see cref="Session"/>, which carries the project,
/// the values and every change notification. Five files, one per menu of the window (this one: state and panes; .Files,
/// .Line, .Alarms, .Wizard), because the commands of one window share its dirty mark and its services.
/// </summary>
public sealed partial class ShellViewModel : ObservableObject
{
    public const string AppName = "Operator Panel";

    /// <summary>The WPF filter text for project files.</summary>
    public const string ProjectFilter = "Operator Panel projects (*.opproj)|*.opproj";

    private readonly ShellServices _services;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;

    public ShellViewModel(PanelSession session, PanelOptions options, ShellServices services, TimeProvider? time = null, ILogger? logger = null)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(services);
        (Session, Options, _services) = (session, options, services);
        _time = time ?? TimeProvider.System;
        _logger = (logger ?? Logger.None).ForContext<ShellViewModel>();
        Inputs = new InputsViewModel(session);
        Outputs = new OutputsViewModel(session, services.Dialogs, options, logger);
        Memory = new MemoryViewModel(session, services.Dialogs, options, logger);
        Diagnostics = new DiagnosticsViewModel(session, services.Dialogs);
        History = new ProjectHistory(session, services.History, session.Dispatcher, _time, _logger);
        _alarms = CreateAlarms(session.Project);
        Trends = new TrendsViewModel(session, History, _time);
        Panes = RegisterPanes(this);
        Docking = new DockingViewModel(services.LayoutPath, Panes);
        Docking.PropertyChanged += OnDockingChanged;
        FollowTrendsPane(Docking["Trends"]);
        GenerateCodeCommand = new RelayCommand(OpenGenerateCode, () => HasProject);
        session.ProjectChanged += OnProjectChanged;
        session.PropertyChanged += OnSessionChanged;
        History.PropertyChanged += (_, e) =>
        {
            // Said once when it starts (the historian reports a problem once); the line goes on regardless.
            if (e.PropertyName == nameof(ProjectHistory.Problem) && History.Problem is { } problem)
            {
                StatusLine.ShowError("History not recorded: " + problem);
            }
        };
    }

    /// <summary>A placeholder before any project is opened: no stations, nothing to poll.</summary>
    public static PanelProject NoProject { get; } = new(string.Empty, RefreshSettings.Default, []);

    public PanelSession Session { get; }

    public PanelOptions Options { get; }

    public InputsViewModel Inputs { get; }

    public OutputsViewModel Outputs { get; }

    public MemoryViewModel Memory { get; }

    public DiagnosticsViewModel Diagnostics { get; }

    /// <summary>The project's history database: recording, the journal, the audit (docs/historian.md).</summary>
    public ProjectHistory History { get; }

    /// <summary>The Trends pane's content.</summary>
    public TrendsViewModel Trends { get; }

    public ObservableCollection<StationStatusViewModel> Stations => Session.Stations;

    public StatusLine StatusLine => Session.StatusLine;

    /// <summary>The file the project was opened from or last saved to; null for a new or demo project.</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(Title))]
    public partial string? ProjectPath { get; private set; }

    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(Title))]
    public partial bool IsDirty { get; private set; }

    /// <summary>The sample project on the simulated line.</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(Title))]
    public partial bool IsDemo { get; private set; }

    public bool HasProject => !Session.Project.Stations.IsEmpty;

    /// <summary>"Bottling line 1 * - Operator Panel": the project's name, "*" while unsaved.</summary>
    public string Title => HasProject
        ? $"{ProjectName}{(IsDemo ? " (demo)" : string.Empty)}{(IsDirty ? " *" : string.Empty)} - {AppName}"
        : AppName;

    public string ProjectName =>
        Session.Project.Name is { Length: > 0 } name ? name
        : ProjectPath is { } path ? Path.GetFileNameWithoutExtension(path)
        : "Untitled";

    private void OnProjectChanged(object? sender, ProjectChangedEventArgs e)
    {
        IsDirty = e.Kind == ProjectChangeKind.Edited;
        History.Follow(e.Project, IsDemo ? _services.Demo?.SampleProjectPath : ProjectPath, IsDemo);
        RenewAlarms(e);
        Trends.Follow(e.Project);
        SelectedStationIndex = Math.Clamp(SelectedStationIndex, 0, Math.Max(0, e.Project.Stations.Length - 1));
        OnPropertyChanged(nameof(HasProject));
        OnPropertyChanged(nameof(ProjectName));
        OnPropertyChanged(nameof(Title));
        NotifyCommands();
    }

    /// <summary>The session's state (connected, refresh mode, read-only) is bound where it is shown; the commands follow it.</summary>
    private void OnSessionChanged(object? sender, PropertyChangedEventArgs e) => NotifyCommands();

    private void NotifyCommands()
    {
        foreach (var command in new IRelayCommand[] { SaveCommand, SaveAsCommand, ConnectCommand, DisconnectCommand, RefreshNowCommand, DemoCommand, EditProjectCommand, GenerateCodeCommand, ReadOverPpiCommand, BackToFreeportCommand })
        {
            command.NotifyCanExecuteChanged();
        }
    }
}
