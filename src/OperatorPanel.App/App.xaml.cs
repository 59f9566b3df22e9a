using System.IO;
using System.Windows;
using Microsoft.Extensions.DependencyInjection;
using Serilog;

namespace OperatorPanel.App;

/// <summary>Composition root: logging and the services the views need. Views hold no logic.</summary>
public partial class App : Application
{
    private ServiceProvider? _services;

    protected override void OnStartup(StartupEventArgs e)
    {
        base.OnStartup(e);
        var logFolder = Path.Combine(
            Environment.GetFolderPath(Environment.SpecialFolder.LocalApplicationData),
            "OperatorPanel",
            "logs");
        Log.Logger = new LoggerConfiguration()
            .MinimumLevel.Information()
            .WriteTo.File(Path.Combine(logFolder, "panel-.log"), rollingInterval: RollingInterval.Day, retainedFileCountLimit: 31, shared: true)
            .CreateLogger();

        var services = new ServiceCollection();
        services.AddSingleton(Log.Logger);
        services.AddSingleton(TimeProvider.System);
        services.AddTransient<MainWindow>();
        _services = services.BuildServiceProvider();

        Log.Information("Operator Panel started");
        _services.GetRequiredService<MainWindow>().Show();
    }

    protected override void OnExit(ExitEventArgs e)
    {
        Log.Information("Operator Panel closed");
        _services?.Dispose();
        Log.CloseAndFlush();
        base.OnExit(e);
    }
}
