using System.ComponentModel;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Alarms;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>
/// The Alarms window of the current project and the status bar's alarm count, which stays current while the window is
/// hidden. A new <see cref="AlarmsViewModel"/> is made when the project is replaced, its alarm texts are edited, or it
/// gets a file (its history file lives beside the project, AlarmHistoryFile.PathFor); the old one is disposed.
/// </summary>
public sealed partial class ShellViewModel : IDisposable
{
    private PanelProject _alarmsProject = NoProject;
    private string? _alarmsPath;

    private AlarmsViewModel _alarms;

    /// <summary>The current project's alarms: rows, history, acknowledge, CSV export; the Alarms pane's content.</summary>
    public AlarmsViewModel Alarms => _alarms;

    public int ActiveAlarmCount => Alarms.ActiveCount;

    public int UnacknowledgedAlarmCount => Alarms.UnacknowledgedCount;

    /// <summary>An alarm is active or waits for acknowledgement: the banner and the status bar show it in colour.</summary>
    public bool HasPendingAlarms => ActiveAlarmCount > 0 || UnacknowledgedAlarmCount > 0;

    /// <summary>For the status bar: "2 active, 1 unacknowledged", "no alarms", or "alarms unknown" (AlarmsViewModel.ShortSummary).</summary>
    public string AlarmSummary => Alarms.ShortSummary;

    /// <summary>For the banner: <see cref="AlarmSummary"/> naming the stations whose alarms are unknown ("alarms unknown: Filler offline").</summary>
    public string AlarmBannerText => Alarms.BannerText;

    public void Dispose()
    {
        Session.ProjectChanged -= OnProjectChanged;
        Session.PropertyChanged -= OnSessionChanged;
        Alarms.PropertyChanged -= OnAlarmsChanged;
        Alarms.Dispose();
    }

    private AlarmsViewModel CreateAlarms(PanelProject project, string? path)
    {
        (_alarmsProject, _alarmsPath) = (project, path);
        var alarms = new AlarmsViewModel(project, path, Session.Values, _time, _services.Files, Session.Stations);
        alarms.PropertyChanged += OnAlarmsChanged;
        return alarms;
    }

    private void RenewAlarms(ProjectChangedEventArgs e)
    {
        var replaced = e.Kind == ProjectChangeKind.Replaced;
        if (!replaced && ProjectPath == _alarmsPath && SameAlarms(_alarmsProject, e.Project))
        {
            _alarmsProject = e.Project;
            return;
        }

        var old = Alarms;
        old.PropertyChanged -= OnAlarmsChanged;
        old.Dispose();
        _alarms = CreateAlarms(e.Project, ProjectPath);
        Panes.Single(p => p.Content == old).Content = _alarms;
        OnPropertyChanged(nameof(Alarms));
        NotifyAlarmCounts();
    }

    private static bool SameAlarms(PanelProject a, PanelProject b) =>
        a.Stations.Length == b.Stations.Length
        && a.Stations.Zip(b.Stations).All(p => p.First.Address == p.Second.Address && p.First.Name == p.Second.Name && p.First.Alarms.SequenceEqual(p.Second.Alarms));

    private void OnAlarmsChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName is nameof(AlarmsViewModel.ActiveCount) or nameof(AlarmsViewModel.UnacknowledgedCount) or nameof(AlarmsViewModel.ShortSummary))
        {
            NotifyAlarmCounts();
        }
    }

    private void NotifyAlarmCounts()
    {
        OnPropertyChanged(nameof(ActiveAlarmCount));
        OnPropertyChanged(nameof(UnacknowledgedAlarmCount));
        OnPropertyChanged(nameof(HasPendingAlarms));
        OnPropertyChanged(nameof(AlarmSummary));
        OnPropertyChanged(nameof(AlarmBannerText));
    }
}
