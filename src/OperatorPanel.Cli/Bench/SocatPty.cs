using System.Diagnostics;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// Two pseudo-terminals joined by socat, a null-modem cable in software, for the measured round trip. socat is looked
/// up on PATH; <see cref="Find"/> returns null when it is missing so the caller can say so and fail.
/// </summary>
internal sealed class SocatPty : IDisposable
{
    private static readonly TimeSpan StartupLimit = TimeSpan.FromSeconds(5);
    private static readonly TimeSpan StartupPoll = TimeSpan.FromMilliseconds(20);

    private readonly Process _socat;

    private SocatPty(Process socat, string panelEnd, string plcEnd)
    {
        (_socat, PanelEnd, PlcEnd) = (socat, panelEnd, plcEnd);
    }

    public string PanelEnd { get; }

    public string PlcEnd { get; }

    public static string? Find() =>
        (Environment.GetEnvironmentVariable("PATH") ?? string.Empty)
            .Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries)
            .Select(dir => Path.Combine(dir, "socat"))
            .FirstOrDefault(File.Exists);

    /// <summary>Starts socat and waits, bounded, until both links exist; throws when it cannot.</summary>
    public static async Task<SocatPty> StartAsync(string socatPath, TimeProvider time, CancellationToken cancellationToken)
    {
        var stem = Path.Combine(Path.GetTempPath(), "opanel-bench-" + Guid.NewGuid().ToString("N")[..12]);
        var (panelEnd, plcEnd) = (stem + "-panel", stem + "-plc");
        var start = new ProcessStartInfo(socatPath)
        {
            ArgumentList = { $"pty,raw,echo=0,link={panelEnd}", $"pty,raw,echo=0,link={plcEnd}" },
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        var process = Process.Start(start) ?? throw new InvalidOperationException($"{socatPath} did not start");
        var pty = new SocatPty(process, panelEnd, plcEnd);
        var started = time.GetTimestamp();
        while (!(File.Exists(panelEnd) && File.Exists(plcEnd)))
        {
            if (process.HasExited || time.GetElapsedTime(started) > StartupLimit)
            {
                pty.Dispose();
                throw new InvalidOperationException($"socat did not create its pseudo-terminals within {StartupLimit.TotalSeconds} s");
            }

            await Task.Delay(StartupPoll, time, cancellationToken).ConfigureAwait(false);
        }

        return pty;
    }

    public void Dispose()
    {
        if (!_socat.HasExited)
        {
            _socat.Kill(entireProcessTree: true);
            _socat.WaitForExit();
        }

        _socat.Dispose();
        File.Delete(PanelEnd);
        File.Delete(PlcEnd);
    }
}
