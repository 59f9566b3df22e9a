using System.Windows.Controls;

namespace OperatorPanel.App.Views;

/// <summary>The Inputs window: lamps grouped by input byte; all behaviour is in InputsViewModel.</summary>
public partial class InputsView : UserControl
{
    public InputsView() => InitializeComponent();
}
