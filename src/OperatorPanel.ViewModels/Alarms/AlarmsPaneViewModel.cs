using OperatorPanel.ViewModels.Shell;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// The Alarms pane in <see cref="ShellViewModel.Panes"/>. The pane stays while the project changes (its place in the
/// saved layout and its visibility with it); <see cref="Alarms"/> is the current project's <see cref="AlarmsViewModel"/>,
/// which the view shows through its DataTemplate.
/// </summary>
public sealed class AlarmsPaneViewModel : PaneViewModel
{
    private AlarmsViewModel _alarms;

    public AlarmsPaneViewModel(AlarmsViewModel alarms)
        : base("Alarms", "alarms")
    {
        ArgumentNullException.ThrowIfNull(alarms);
        _alarms = alarms;
    }

    public AlarmsViewModel Alarms
    {
        get => _alarms;
        internal set => SetProperty(ref _alarms, value);
    }
}
