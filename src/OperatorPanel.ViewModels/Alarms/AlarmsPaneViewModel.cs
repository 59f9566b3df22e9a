using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.ViewModels.Shell;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// The Alarms pane in <see cref="ShellViewModel.Panes"/>. The pane stays while the project changes (its place in the
/// saved layout and its visibility with it); <see cref="Alarms"/> is the current project's <see cref="AlarmsViewModel"/>,
/// which the view shows through its DataTemplate.
/// </summary>
public sealed partial class AlarmsPaneViewModel : PaneViewModel
{
    public AlarmsPaneViewModel(AlarmsViewModel alarms)
        : base("Alarms", "alarms")
    {
        ArgumentNullException.ThrowIfNull(alarms);
        Alarms = alarms;
    }

    [ObservableProperty]
    public partial AlarmsViewModel Alarms { get; internal set; }
}
