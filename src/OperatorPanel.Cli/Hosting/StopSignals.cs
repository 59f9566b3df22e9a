using System.Runtime.InteropServices;

namespace OperatorPanel.Cli.Hosting;

/// <summary>
/// Ends a long-running verb (simulate, watch, write): Ctrl+C, SIGTERM (systemd, docker stop), or an optional duration,
/// whichever comes first. The first Ctrl+C is taken over so the verb can finish what is on the wire and print its
/// summary instead of being killed; a second Ctrl+C ends the program at once (exit 130), as a user pressing it twice means.
/// </summary>
internal sealed class StopSignals : IDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly PosixSignalRegistration? _sigterm;
    private readonly Action? _onFirstPress;
    private int _presses;

    /// <param name="duration">Stop after this long; null for no limit.</param>
    /// <param name="onFirstPress">Says what happens now (e.g. "stopping after the write on the wire"); called on the first Ctrl+C.</param>
    public StopSignals(TimeSpan? duration, Action? onFirstPress = null)
    {
        _onFirstPress = onFirstPress;
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
                if (Interlocked.Increment(ref _presses) > 1)
                {
                    return; // asked twice: end now
                }

                context.Cancel = true;
                _stop.Cancel();
                _onFirstPress?.Invoke();
            });
        }
        catch (PlatformNotSupportedException)
        {
            // Some platforms deliver no SIGTERM to managed code; Ctrl+C and the duration still work.
            return null;
        }
    }

    public bool IsStopRequested => _stop.IsCancellationRequested;

    private void OnCancelKeyPress(object? sender, ConsoleCancelEventArgs e)
    {
        if (Interlocked.Increment(ref _presses) > 1)
        {
            return; // the second press: the runtime ends the program (130)
        }

        e.Cancel = true;
        _stop.Cancel();
        _onFirstPress?.Invoke();
    }
}
