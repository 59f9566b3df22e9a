using System.ComponentModel;
using System.Windows;
using System.Windows.Automation;
using System.Windows.Controls;
using System.Windows.Data;
using System.Windows.Media;
using OperatorPanel.App.Generate;
using OperatorPanel.App.Views;
using OperatorPanel.ViewModels.Docking;
using OperatorPanel.ViewModels.Shell;

namespace OperatorPanel.App;

/// <summary>
/// The shell window. Code-behind is visual only: it places the pane views in the docking host, fills the View menu
/// from the panes, zooms the window for Large display as DockingViewModel.FitZoom says, shows Generate PLC code while
/// the shell has one open, and turns the window's Closing into the shell's "save changes?" question.
/// </summary>
public partial class MainWindow : Window
{
    private readonly ShellViewModel _shell;
    private readonly DockingViewModel _docking;
    private bool _closeConfirmed;
    private GenerateCodeWindow? _generateWindow;

    public MainWindow(ShellViewModel shell, DockingViewModel docking)
    {
        ArgumentNullException.ThrowIfNull(shell);
        ArgumentNullException.ThrowIfNull(docking);
        _shell = shell;
        _docking = docking;
        DataContext = shell;
        InitializeComponent();
        ResetLayoutItem.Command = docking.ResetLayoutCommand;
        foreach (var pane in docking.Panes)
        {
            var item = new MenuItem { Header = pane.Title, IsCheckable = true, DataContext = pane };
            item.SetBinding(MenuItem.IsCheckedProperty, new Binding(nameof(DockPaneViewModel.IsVisible)) { Mode = BindingMode.TwoWay });
            AutomationProperties.SetAutomationId(item, $"Show{pane.Id}MenuItem");
            ViewMenu.Items.Add(item);
        }

        Docking.Initialize(docking, CreateView, this);
        // The Trends window redraws from the history every second only while it is shown.
        var trends = docking[DockPaneId.Trends];
        shell.Trends.IsVisible = trends.IsVisible;
        trends.PropertyChanged += (_, e) => shell.Trends.IsVisible = e.PropertyName == nameof(DockPaneViewModel.IsVisible) ? trends.IsVisible : shell.Trends.IsVisible;
        shell.PropertyChanged += OnShellChanged;

        BindingOperations.SetBinding(ZoomTransform, ScaleTransform.ScaleXProperty, new Binding(nameof(DockingViewModel.Zoom)) { Source = docking });
        BindingOperations.SetBinding(ZoomTransform, ScaleTransform.ScaleYProperty, new Binding(nameof(DockingViewModel.Zoom)) { Source = docking });
        LargeDisplayItem.SetBinding(MenuItem.InputGestureTextProperty, new Binding(nameof(DockingViewModel.ZoomText)) { Source = docking });
        SizeChanged += (_, _) => FitZoom();
        // Shown or hidden as alarms come and go; one line high, so its height does not depend on the zoom.
        AlarmBanner.SizeChanged += (_, _) => FitZoom();
        shell.Options.PropertyChanged += (_, e) => FitZoom();
        foreach (var pane in docking.Panes)
        {
            pane.PropertyChanged += (_, e) =>
            {
                if (e.PropertyName is nameof(DockPaneViewModel.IsVisible) or nameof(DockPaneViewModel.Placement))
                {
                    FitZoom();
                }
            };
        }
    }

    protected override async void OnClosing(CancelEventArgs e)
    {
        ArgumentNullException.ThrowIfNull(e);
        base.OnClosing(e);
        if (_closeConfirmed)
        {
            return;
        }

        e.Cancel = true;
        if (await _shell.CloseAsync())
        {
            _closeConfirmed = true;
            _docking.Save();
            Docking.CloseFloatingWindows();
            // Closed again after this Closing has returned: when the shell answers at once (no line to disconnect), the
            // await does not yield and WPF refuses Close() from inside Closing.
            _ = Dispatcher.InvokeAsync(Close);
        }
    }

    /// <summary>
    /// The client area (the zoomed root's parent) and the unzoomed height of menu, banner and status bar go to the view
    /// model.
    /// </summary>
    private void FitZoom()
    {
        if (VisualTreeHelper.GetParent(Root) is FrameworkElement client)
        {
            var chrome = MainMenu.ActualHeight + AlarmBanner.ActualHeight + StatusBar.ActualHeight;
            _docking.FitZoom(client.ActualWidth, client.ActualHeight, chrome, _shell.Options.LargeDisplay);
        }
    }

    private FrameworkElement CreateView(DockPaneId id)
    {
        FrameworkElement view = id switch
        {
            DockPaneId.Inputs => new InputsView(),
            DockPaneId.Outputs => new OutputsView(),
            DockPaneId.Memory => new MemoryView(),
            DockPaneId.Alarms => new AlarmsView(),
            DockPaneId.Diagnostics => new DiagnosticsView(),
            DockPaneId.Trends => new TrendsView(),
        };
        view.SetBinding(DataContextProperty, new Binding(id.ToString()) { Source = _shell });
        return view;
    }

    private void OnExit(object sender, RoutedEventArgs e) => Close();

    private void OnShellChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName == nameof(ShellViewModel.GenerateCode))
        {
            ShowGenerateCode();
        }
    }

    /// <summary>One Generate PLC code window, following the shell: opened, given the new view model, or closed.</summary>
    private void ShowGenerateCode()
    {
        if (_shell.GenerateCode is not { } generate)
        {
            var open = _generateWindow;
            _generateWindow = null;
            open?.Close();
            return;
        }

        if (_generateWindow is null)
        {
            _generateWindow = new GenerateCodeWindow(generate) { Owner = this };
            _generateWindow.Closed += OnGenerateCodeClosed;
            _generateWindow.Show();
        }
        else
        {
            _generateWindow.DataContext = generate;
            _generateWindow.Activate();
        }
    }

    private void OnGenerateCodeClosed(object? sender, EventArgs e)
    {
        if (ReferenceEquals(sender, _generateWindow))
        {
            _generateWindow = null;
            _shell.CloseGenerateCode();
        }
    }
}
