using System.Windows;
using System.Windows.Automation;
using System.Windows.Controls;
using System.Windows.Input;
using System.Windows.Media;
using System.Windows.Shapes;
using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.App.Docking;

/// <summary>A pane's tab header: its title, a float button, a hide button, and a menu to dock it to another side.</summary>
public sealed class DockPaneHeader : StackPanel
{
    // Drawn, not typed: a glyph such as U+29C9 needs a font that has it, and many PCs (and Wine) show a box instead.
    private static readonly Geometry FloatIcon = Geometry.Parse("M1,4 H8 V11 H1 Z M4,4 V1 H11 V8 H8");
    private static readonly Geometry HideIcon = Geometry.Parse("M1.5,1.5 L10.5,10.5 M10.5,1.5 L1.5,10.5");

    public DockPaneHeader(DockPaneViewModel pane)
    {
        ArgumentNullException.ThrowIfNull(pane);
        Orientation = Orientation.Horizontal;
        Children.Add(new TextBlock { Text = pane.Title, VerticalAlignment = VerticalAlignment.Center, Margin = new Thickness(0, 0, 6, 0) });
        Children.Add(Button("Float", FloatIcon, pane.FloatCommand, $"{pane.AutomationId}Float"));
        Children.Add(Button("Hide (View menu shows it again)", HideIcon, pane.HideCommand, $"{pane.AutomationId}Hide"));

        var menu = new ContextMenu();
        foreach (var placement in new[] { DockPlacement.Left, DockPlacement.Right, DockPlacement.Bottom, DockPlacement.Center })
        {
            menu.Items.Add(MenuItem($"Dock {placement.ToString().ToLowerInvariant()}", pane.DockCommand, placement, $"{pane.AutomationId}Dock{placement}"));
        }

        menu.Items.Add(MenuItem("Float", pane.FloatCommand, null, $"{pane.AutomationId}FloatMenu"));
        ContextMenu = menu;
    }

    /// <summary>
    /// A context menu item made in code, before it is in any menu: its content alignment is set here, or the theme's
    /// binding of it to the parent menu finds none and WPF logs a binding error.
    /// </summary>
    private static MenuItem MenuItem(string header, ICommand command, object? parameter, string automationId)
    {
        var item = new MenuItem
        {
            Header = header,
            Command = command,
            CommandParameter = parameter,
            HorizontalContentAlignment = HorizontalAlignment.Left,
            VerticalContentAlignment = VerticalAlignment.Center,
        };
        AutomationProperties.SetAutomationId(item, automationId);
        return item;
    }

    private static Button Button(string tip, Geometry icon, ICommand command, string automationId)
    {
        var glyph = new Path { Data = icon, Width = 12, Height = 12, StrokeThickness = 1.5, Stretch = Stretch.None };
        glyph.SetResourceReference(Shape.StrokeProperty, SystemColors.ControlTextBrushKey);
        var button = new Button
        {
            Content = glyph,
            ToolTip = tip,
            Command = command,
            Padding = new Thickness(4),
            Margin = new Thickness(1, 0, 1, 0),
            MinWidth = 0,
            MinHeight = 0,
            BorderThickness = new Thickness(0),
            Background = Brushes.Transparent,
            VerticalAlignment = VerticalAlignment.Center,
        };
        AutomationProperties.SetAutomationId(button, automationId);
        AutomationProperties.SetName(button, tip);
        return button;
    }
}
