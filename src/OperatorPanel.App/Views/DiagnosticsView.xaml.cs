using System.Windows.Controls;

namespace OperatorPanel.App.Views;

/// <summary>Diagnostics: CPU identified vs project, RUN/STOP, scan times, link statistics per station.</summary>
public partial class DiagnosticsView : UserControl
{
    public DiagnosticsView() => InitializeComponent();
}
