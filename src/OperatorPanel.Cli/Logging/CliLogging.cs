using Serilog;
using Serilog.Core;
using Serilog.Events;

namespace OperatorPanel.Cli.Logging;

/// <summary>
/// Serilog for the CLI: a rolling daily file under the user's local application data folder, and the console
/// (always stderr, so stdout stays clean for --json and scripts). Logging never throws: an unwritable log folder
/// leaves the console sink alone.
/// </summary>
internal static class CliLogging
{
    public static string DefaultLogFolder { get; } = Path.Combine(
        Environment.GetFolderPath(Environment.SpecialFolder.LocalApplicationData, Environment.SpecialFolderOption.Create),
        "OperatorPanel",
        "logs");

    public static Logger Create(LogEventLevel fileLevel, LogEventLevel consoleLevel, string? folder)
    {
        var configuration = new LoggerConfiguration()
            .MinimumLevel.Is(Min(fileLevel, consoleLevel))
            .Enrich.WithProperty("App", "opanel")
            .WriteTo.Console(restrictedToMinimumLevel: consoleLevel, standardErrorFromLevel: LogEventLevel.Verbose, outputTemplate: "opanel [{Level:u3}] {Message:lj}{NewLine}{Exception}");

        var logFolder = folder ?? DefaultLogFolder;
        if (TryEnsureFolder(logFolder))
        {
            configuration = configuration.WriteTo.File(
                Path.Combine(logFolder, "opanel-.log"),
                restrictedToMinimumLevel: fileLevel,
                rollingInterval: RollingInterval.Day,
                retainedFileCountLimit: 31,
                fileSizeLimitBytes: 20 * 1024 * 1024,
                rollOnFileSizeLimit: true,
                shared: true,
                outputTemplate: "{Timestamp:yyyy-MM-dd HH:mm:ss.fff zzz} [{Level:u3}] {Message:lj} {Properties}{NewLine}{Exception}");
        }

        return configuration.CreateLogger();
    }

    private static LogEventLevel Min(LogEventLevel a, LogEventLevel b) => a < b ? a : b;

    private static bool TryEnsureFolder(string folder)
    {
        try
        {
            Directory.CreateDirectory(folder);
            return true;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            return false;
        }
    }
}
