using System.IO;
using System.Windows;
using System.Windows.Threading;
using Microsoft.Extensions.DependencyInjection;
using OperatorPanel.App.Services;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Transport;
using OperatorPanel.Historian;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Shell;
using OperatorPanel.ViewModels.Wizard;
using Serilog;

namespace OperatorPanel.App;

/// <summary>
/// Composition root: logging, the services the view models need, the shell. Views hold no logic. Start-up: a project
/// path on the command line opens it; <c>--demo</c>, or a PC with no serial port at all, opens the demo line.
/// </summary>
public partial class App : Application
{
    private ServiceProvider? _services;

    private static string UserFolder => Path.Combine(Environment.GetFolderPath(Environment.SpecialFolder.LocalApplicationData), "OperatorPanel");

    protected override async void OnStartup(StartupEventArgs e)
    {
        ArgumentNullException.ThrowIfNull(e);
        base.OnStartup(e);
        Log.Logger = new LoggerConfiguration()
            .MinimumLevel.Information()
            .WriteTo.File(Path.Combine(UserFolder, "logs", "panel-.log"), rollingInterval: RollingInterval.Day, retainedFileCountLimit: 31, shared: true)
            .CreateLogger();
        DispatcherUnhandledException += OnUnhandled;
        BindingErrorLog.Attach(Log.Logger);

        ShellViewModel shell;
        try
        {
            _services = Compose();
            shell = _services.GetRequiredService<ShellViewModel>();
            shell.Docking.Load();
            _services.GetRequiredService<LiveValueWitness>();
            _services.GetRequiredService<TrendWitness>();
            var window = new MainWindow(shell);
            MainWindow = window;
            window.Closed += OnMainWindowClosed;
            window.Show();
        }
        catch (Exception failure) when (failure is not OutOfMemoryException)
        {
            // Never a process without a window: what cannot be shown is said, logged, and the panel ends.
            Log.Fatal(failure, "The panel could not start");
            MessageBox.Show($"Operator Panel could not start: {failure.Message}", "Operator Panel", MessageBoxButton.OK, MessageBoxImage.Error);
            Log.CloseAndFlush();
            Shutdown(1);
            return;
        }

        Log.Information("Operator Panel {Version} started", typeof(App).Assembly.GetName().Version);

        var project = e.Args.FirstOrDefault(a => !a.StartsWith("--", StringComparison.Ordinal));
        if (project is not null)
        {
            // A double-clicked .opproj arrives here (the installer's open verb passes its path); the log says what became of it.
            if (await shell.OpenFileAsync(project))
            {
                Log.Information("Opened {Path} from the command line: {Project}", project, shell.ProjectName);
            }
        }
        else if (e.Args.Contains("--demo") || SerialPortDiscovery.List().Count == 0)
        {
            await shell.DemoCommand.ExecuteAsync(null);
        }
    }

    protected override void OnExit(ExitEventArgs e)
    {
        Log.Information("Operator Panel closed");
        Log.CloseAndFlush();
        base.OnExit(e);
    }

    /// <summary>
    /// The shell has closed (its line is disconnected): options are saved and the services disposed while the dispatcher
    /// still runs, because the session is only asynchronously disposable; then the application ends (explicit shutdown).
    /// </summary>
    private async void OnMainWindowClosed(object? sender, EventArgs e)
    {
        if (_services is { } services)
        {
            _services = null;
            services.GetRequiredService<PanelOptionsStore>().Save(services.GetRequiredService<PanelOptions>());
            // The shell has disconnected (or given up waiting on a port, ShellViewModel.CloseWait); a port that still will
            // not let go must not hold the closing panel either.
            var disposing = services.DisposeAsync().AsTask();
            if (await Task.WhenAny(disposing, Task.Delay(ShellViewModel.CloseWait)) != disposing)
            {
                Log.Warning("The panel's services did not stop within {Seconds} s; the panel closes without waiting for them", ShellViewModel.CloseWait.TotalSeconds);
            }
        }

        Shutdown();
    }

    private ServiceProvider Compose()
    {
        var services = new ServiceCollection();
        services.AddSingleton(Log.Logger);
        services.AddSingleton(TimeProvider.System);
        services.AddSingleton<IUiDispatcher>(new WpfDispatcher(Dispatcher));
        services.AddSingleton<IDialogService, WpfDialogService>();
        services.AddSingleton<IFileDialogService, WpfFileDialogService>();
        services.AddSingleton(sp => new PanelOptionsStore(Path.Combine(UserFolder, "options.json"), sp.GetRequiredService<ILogger>()));
        services.AddSingleton(sp => sp.GetRequiredService<PanelOptionsStore>().Load());
        // The write journal sits beside the logs, where opanel keeps its own: a write cut short by either is settled by the next.
        services.AddSingleton(sp => new PanelSession(
            ShellViewModel.NoProject, sp.GetRequiredService<IUiDispatcher>(), TimeProvider.System, sp.GetRequiredService<ILogger>(),
            WriteJournal.In(Path.Combine(UserFolder, "logs"))));
        services.AddSingleton(sp => new WpfAlarmSound(sp.GetRequiredService<ILogger>()));
        services.AddSingleton(sp =>
        {
            var presenter = new WizardPresenter();
            var tester = new LinkConnectionTester(settings => new SerialPortTransport(settings), TimeProvider.System);
            var ports = new SystemSerialPortCatalog();
            return new ShellServices(
                sp.GetRequiredService<IDialogService>(),
                sp.GetRequiredService<IFileDialogService>(),
                new SerialLineConnector(sp.GetRequiredService<ILogger>()),
                new DemoSource(sp.GetRequiredService<ILogger>()),
                // File > New tests a port like Edit project does: never one the connected panel is polling on.
                new WizardProjectSource(presenter, new PortInUseGuard(tester, sp.GetRequiredService<PanelSession>()), ports),
                presenter,
                tester,
                ports,
                Path.Combine(UserFolder, "layout.json"),
                Path.Combine(AppContext.BaseDirectory, "README.txt"),
                new ShellDocumentLauncher(),
                HistoryFolder.Default,
                sp.GetRequiredService<WpfAlarmSound>(),
                Path.Combine(UserFolder, "print"));
        });
        services.AddSingleton(sp => new ShellViewModel(
            sp.GetRequiredService<PanelSession>(),
            sp.GetRequiredService<PanelOptions>(),
            sp.GetRequiredService<ShellServices>(),
            TimeProvider.System,
            sp.GetRequiredService<ILogger>()));
        services.AddSingleton(sp => new LiveValueWitness(sp.GetRequiredService<ShellViewModel>().Memory, Dispatcher, sp.GetRequiredService<ILogger>()));
        services.AddSingleton(sp => new TrendWitness(sp.GetRequiredService<ShellViewModel>().Trends, Dispatcher, sp.GetRequiredService<ILogger>()));
        return services.BuildServiceProvider();
    }

    /// <summary>
    /// A fault in a view or command is logged and shown; the panel goes on (the line keeps being watched). The log line
    /// starts "Unhandled error" (installer/wine-smoke.sh fails on it).
    /// </summary>
    private void OnUnhandled(object sender, DispatcherUnhandledExceptionEventArgs e)
    {
        Log.Error(e.Exception, "Unhandled error in the panel");
        const string Caption = "Operator Panel: unexpected error";
        if (MainWindow is { IsLoaded: true } owner)
        {
            MessageBox.Show(owner, e.Exception.Message, Caption, MessageBoxButton.OK, MessageBoxImage.Error);
        }
        else
        {
            MessageBox.Show(e.Exception.Message, Caption, MessageBoxButton.OK, MessageBoxImage.Error);
        }

        e.Handled = true;
    }
}
