using System.ComponentModel;
using System.Windows;
using System.Windows.Media;
using OperatorPanel.App.Generate;
using OperatorPanel.App.Help;
using OperatorPanel.ViewModels.Docking;
using OperatorPanel.ViewModels.Shell;

namespace OperatorPanel.App;

/// <summary>
/// The shell window. Code-behind is visual only: it hands the docking host its panes, feeds DockingViewModel.FitZoom
/// the window's size for Large display, puts the window where the layout says and remembers where it was, shows
/// Generate PLC code while the shell has one open and Help > About as a dialog, and turns the window's Closing into the shell's "save changes?"
/// question.
/// </summary>
public partial class MainWindow : Window
{
    private readonly ShellViewModel _shell;
    private bool _closeConfirmed;
    private GenerateCodeWindow? _generateWindow;

    public MainWindow(ShellViewModel shell)
    {
        ArgumentNullException.ThrowIfNull(shell);
        _shell = shell;
        DataContext = shell;
        InitializeComponent();
        Place(shell.Docking.Window);
        Docking.Initialize(shell.Docking, this);
        shell.PropertyChanged += OnShellChanged;

        SizeChanged += (_, _) => FitZoom();
        AlarmBanner.SizeChanged += (_, _) => FitZoom();
        shell.Options.PropertyChanged += (_, _) => FitZoom();
        foreach (var pane in shell.Docking.Panes)
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
            _shell.Docking.Window = Placement();
            _shell.Docking.Save();
            Docking.CloseFloatingWindows();
            // Closed again after this Closing has returned: when the shell answers at once (no line to disconnect), the
            // await does not yield and WPF refuses Close() from inside Closing.
            _ = Dispatcher.InvokeAsync(Close);
        }
    }

    /// <summary>Where the layout file says, moved onto today's desktop; the system places a window saved without a position.</summary>
    private void Place(WindowPlacement? saved)
    {
        var desktop = (SystemParameters.VirtualScreenLeft, SystemParameters.VirtualScreenTop, SystemParameters.VirtualScreenWidth, SystemParameters.VirtualScreenHeight);
        var place = (saved ?? WindowPlacement.Default).FitTo(desktop);
        (Width, Height) = (place.Width, place.Height);
        if (double.IsFinite(place.Left) && double.IsFinite(place.Top))
        {
            WindowStartupLocation = WindowStartupLocation.Manual;
            (Left, Top) = (place.Left, place.Top);
        }
        else
        {
            WindowStartupLocation = WindowStartupLocation.CenterScreen;
        }

        WindowState = place.Maximized ? WindowState.Maximized : WindowState.Normal;
    }

    /// <summary>The normal bounds (also while maximised or minimised) and whether the window is maximised.</summary>
    private WindowPlacement Placement()
    {
        var bounds = WindowState == WindowState.Normal ? new Rect(Left, Top, ActualWidth, ActualHeight) : RestoreBounds;
        return bounds.IsEmpty
            ? WindowPlacement.Default with { Maximized = WindowState == WindowState.Maximized }
            : new WindowPlacement(bounds.Left, bounds.Top, bounds.Width, bounds.Height, WindowState == WindowState.Maximized);
    }

    /// <summary>The client area (the zoomed root's parent) and the unzoomed height of menu, banner and status bar go to the view model.</summary>
    private void FitZoom()
    {
        if (VisualTreeHelper.GetParent(Root) is FrameworkElement client)
        {
            var chrome = MainMenu.ActualHeight + AlarmBanner.ActualHeight + StatusBar.ActualHeight;
            _shell.Docking.FitZoom(client.ActualWidth, client.ActualHeight, chrome, _shell.Options.LargeDisplay);
        }
    }

    private void OnExit(object sender, RoutedEventArgs e) => Close();

    private void OnShellChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName == nameof(ShellViewModel.GenerateCode))
        {
            ShowGenerateCode();
        }

        if (e.PropertyName == nameof(ShellViewModel.About) && _shell.About is { } about)
        {
            new AboutWindow(about) { Owner = this }.ShowDialog();
            _shell.CloseAbout();
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
