using System.Windows;
using System.Windows.Automation;
using System.Windows.Controls;
using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.App.Docking;

/// <summary>A pane's tab header: its title, a float button, a hide button, and a menu to dock it to another side.</summary>
public sealed class DockPaneHeader : StackPanel
{
    public DockPaneHeader(DockPaneViewModel pane)
    {
        ArgumentNullException.ThrowIfNull(pane);
        Orientation = Orientation.Horizontal;
        Children.Add(new TextBlock { Text = pane.Title, VerticalAlignment = VerticalAlignment.Center, Margin = new Thickness(0, 0, 6, 0) });
        Children.Add(Button("Float", "\u29C9", pane.FloatCommand, null, $"{pane.AutomationId}Float"));
        Children.Add(Button("Hide (View menu shows it again)", "\u2715", pane.HideCommand, null, $"{pane.AutomationId}Hide"));

        var menu = new ContextMenu();
        foreach (var placement in new[] { DockPlacement.Left, DockPlacement.Right, DockPlacement.Bottom, DockPlacement.Center })
        {
            var item = new MenuItem { Header = $"Dock {placement.ToString().ToLowerInvariant()}", Command = pane.DockCommand, CommandParameter = placement };
            AutomationProperties.SetAutomationId(item, $"{pane.AutomationId}Dock{placement}");
            menu.Items.Add(item);
        }

        var floatItem = new MenuItem { Header = "Float", Command = pane.FloatCommand };
        AutomationProperties.SetAutomationId(floatItem, $"{pane.AutomationId}FloatMenu");
        menu.Items.Add(floatItem);
        ContextMenu = menu;
    }

    private static Button Button(string tip, string glyph, System.Windows.Input.ICommand command, object? parameter, string automationId)
    {
        var button = new Button
        {
            Content = glyph,
            ToolTip = tip,
            Command = command,
            CommandParameter = parameter,
            Padding = new Thickness(3, 0, 3, 0),
            Margin = new Thickness(1, 0, 1, 0),
            BorderThickness = new Thickness(0),
            Background = System.Windows.Media.Brushes.Transparent,
        };
        AutomationProperties.SetAutomationId(button, automationId);
        AutomationProperties.SetName(button, tip);
        return button;
    }
}
