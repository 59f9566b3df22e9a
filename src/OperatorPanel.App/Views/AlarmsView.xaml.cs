using System.Windows.Controls;

namespace OperatorPanel.App.Views;

/// <summary>The Alarms window; all behaviour is in AlarmsViewModel.</summary>
public partial class AlarmsView : UserControl
{
    public AlarmsView() => InitializeComponent();
}
