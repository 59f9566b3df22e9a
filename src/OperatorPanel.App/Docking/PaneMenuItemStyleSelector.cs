using System.Windows;
using System.Windows.Controls;
using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.App.Docking;

/// <summary>
/// The View menu lists the panes (bound to DockingViewModel.Panes) beside fixed items: the pane style goes to the items
/// made for panes only, so the fixed menu items keep the theme's own style.
/// </summary>
public sealed class PaneMenuItemStyleSelector : StyleSelector
{
    public Style? PaneStyle { get; set; }

    public override Style? SelectStyle(object item, DependencyObject container) => item is DockPaneViewModel ? PaneStyle : null;
}
