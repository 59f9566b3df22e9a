using System.Windows.Controls;

namespace OperatorPanel.App.Views;

/// <summary>The Outputs window: lamps with switches; all behaviour is in OutputsViewModel.</summary>
public partial class OutputsView : UserControl
{
    public OutputsView() => InitializeComponent();
}
