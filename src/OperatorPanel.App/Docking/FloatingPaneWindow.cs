using System.ComponentModel;
using System.Windows;
using System.Windows.Automation;
using System.Windows.Controls;
using System.Windows.Data;
using System.Windows.Media;
using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.App.Docking;

/// <summary>
/// The window of a floating pane: a Dock button above the pane's view (back to where it was docked), the view zoomed
/// as Large display says (<see cref="DockingViewModel.FloatingZoom"/>). Its position and size go back to the pane's
/// <see cref="DockPaneViewModel.Float"/>; closing it with the window's close button hides the pane (the View menu shows
/// it again) instead of losing it.
/// </summary>
public sealed class FloatingPaneWindow : Window
{
    private readonly DockPaneViewModel _pane;
    private readonly ContentControl _host = new() { Focusable = false, IsTabStop = false };
    private bool _releasing;

    public FloatingPaneWindow(DockPaneViewModel pane, UIElement view, DockingViewModel docking)
    {
        ArgumentNullException.ThrowIfNull(pane);
        ArgumentNullException.ThrowIfNull(docking);
        _pane = pane;
        Title = pane.Title;
        ShowInTaskbar = false;
        WindowStartupLocation = WindowStartupLocation.Manual;
        Left = pane.Float.Left;
        Top = pane.Float.Top;
        Width = pane.Float.Width;
        Height = pane.Float.Height;
        AutomationProperties.SetAutomationId(this, $"{pane.AutomationId}Window");

        var dock = new Button
        {
            Content = "Dock to the main window",
            Command = pane.DockBackCommand,
            Padding = new Thickness(10, 2, 10, 2),
            Margin = new Thickness(4),
            HorizontalAlignment = HorizontalAlignment.Left,
            ToolTip = "Put this window back where it was docked in the main window",
        };
        AutomationProperties.SetAutomationId(dock, $"{pane.AutomationId}DockBack");
        DockPanel.SetDock(dock, System.Windows.Controls.Dock.Top);
        _host.Content = view;
        var zoom = new ScaleTransform();
        BindingOperations.SetBinding(zoom, ScaleTransform.ScaleXProperty, new Binding(nameof(DockingViewModel.FloatingZoom)) { Source = docking });
        BindingOperations.SetBinding(zoom, ScaleTransform.ScaleYProperty, new Binding(nameof(DockingViewModel.FloatingZoom)) { Source = docking });
        Content = new DockPanel { Children = { dock, _host }, LayoutTransform = zoom };
        LocationChanged += (_, _) => Remember();
        SizeChanged += (_, _) => Remember();
    }

    /// <summary>Takes the view back for docking; the window is closed next.</summary>
    public UIElement? Release()
    {
        _releasing = true;
        var view = _host.Content as UIElement;
        _host.Content = null;
        return view;
    }

    protected override void OnClosing(CancelEventArgs e)
    {
        ArgumentNullException.ThrowIfNull(e);
        if (!_releasing)
        {
            // The close button hides the pane; the docking host then closes this window itself. Not from inside this
            // Closing: WPF refuses to close (or hide) a window while it is closing ("Cannot set Visibility ...").
            e.Cancel = true;
            Dispatcher.BeginInvoke(() => _pane.IsVisible = false);
        }

        base.OnClosing(e);
    }

    private void Remember()
    {
        if (WindowState == WindowState.Normal && !_releasing)
        {
            _pane.Float = new FloatBounds(Left, Top, ActualWidth, ActualHeight);
        }
    }
}
