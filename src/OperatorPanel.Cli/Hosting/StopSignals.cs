using System.Runtime.InteropServices;

namespace OperatorPanel.Cli.Hosting;

/// <summary>
/// Ends a long-running verb (simulate, watch): Ctrl+C, SIGTERM (systemd, docker stop), or an optional duration,
/// whichever comes first. Ctrl+C is taken over so the verb can print its summary instead of being killed.
/// </summary>
internal sealed class StopSignals : IDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly PosixSignalRegistration? _sigterm;

    public StopSignals(TimeSpan? duration)
    {
        Console.CancelKeyPress += OnCancelKeyPress;
        _sigterm = TryRegisterSigterm();
        if (duration is { } limit)
        {
            _stop.CancelAfter(limit);
        }
    }

    public CancellationToken Token => _stop.Token;

    public void Dispose()
    {
        Console.CancelKeyPress -= OnCancelKeyPress;
        _sigterm?.Dispose();
        _stop.Dispose();
    }

    private PosixSignalRegistration? TryRegisterSigterm()
    {
        try
        {
            return PosixSignalRegistration.Create(PosixSignal.SIGTERM, context =>
            {
                context.Cancel = true;
                _stop.Cancel();
            });
        }
        catch (PlatformNotSupportedException)
        {
            // Some platforms deliver no SIGTERM to managed code; Ctrl+C and the duration still work.
            return null;
        }
    }

    private void OnCancelKeyPress(object? sender, ConsoleCancelEventArgs e)
    {
        e.Cancel = true;
        _stop.Cancel();
    }
}
