using System.ComponentModel;
using System.Windows;
using System.Windows.Automation;
using OperatorPanel.ViewModels.Docking;

namespace OperatorPanel.App.Docking;

/// <summary>
/// The window of a floating pane. Its position and size go back to the pane's <see cref="DockPaneViewModel.Float"/>;
/// closing it with the window's close button hides the pane (the View menu shows it again) instead of losing it.
/// </summary>
public sealed class FloatingPaneWindow : Window
{
    private readonly DockPaneViewModel _pane;
    private bool _releasing;

    public FloatingPaneWindow(DockPaneViewModel pane, UIElement view)
    {
        ArgumentNullException.ThrowIfNull(pane);
        _pane = pane;
        Title = pane.Title;
        Content = view;
        ShowInTaskbar = false;
        WindowStartupLocation = WindowStartupLocation.Manual;
        Left = pane.Float.Left;
        Top = pane.Float.Top;
        Width = pane.Float.Width;
        Height = pane.Float.Height;
        AutomationProperties.SetAutomationId(this, $"{pane.AutomationId}Window");
        LocationChanged += (_, _) => Remember();
        SizeChanged += (_, _) => Remember();
    }

    /// <summary>Takes the view back for docking; the window is closed next.</summary>
    public UIElement? Release()
    {
        _releasing = true;
        var view = Content as UIElement;
        Content = null;
        return view;
    }

    protected override void OnClosing(CancelEventArgs e)
    {
        ArgumentNullException.ThrowIfNull(e);
        if (!_releasing)
        {
            e.Cancel = true;
            _pane.IsVisible = false;
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
