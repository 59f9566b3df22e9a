using System.Diagnostics;

namespace OperatorPanel.TestKit;

/// <summary>
/// Two pseudo-terminals joined by socat, a null-modem cable in software: what is written to <see cref="PathA"/>
/// comes out of <see cref="PathB"/> and back. A missing socat fails the test; it never skips (house style).
/// </summary>
public sealed class SocatPtyPair : IDisposable
{
    private static readonly TimeSpan StartupLimit = TimeSpan.FromSeconds(5);

    private readonly Process _socat;

    private SocatPtyPair(Process socat, string pathA, string pathB)
    {
        _socat = socat;
        PathA = pathA;
        PathB = pathB;
    }

    public string PathA { get; }

    public string PathB { get; }

    /// <summary>Starts socat and waits (real time, bounded) until both links exist.</summary>
    public static Task<SocatPtyPair> StartAsync()
    {
        var stem = Path.Combine(Path.GetTempPath(), "opanel-pty-" + Guid.NewGuid().ToString("N")[..12]);
        return StartAsync(stem + "-a", stem + "-b");
    }

    /// <summary>
    /// Starts socat with its links at the given paths: after <see cref="Kill"/>, the same paths again are the USB
    /// adapter plugged back in under its old name (new pseudo-terminals behind the links).
    /// </summary>
    public static async Task<SocatPtyPair> StartAsync(string pathA, string pathB)
    {
        var socat = FindSocat() ?? throw new InvalidOperationException("socat not found: install Debian package socat");
        var start = new ProcessStartInfo(socat)
        {
            ArgumentList = { "-d", "-d", $"pty,raw,echo=0,link={pathA}", $"pty,raw,echo=0,link={pathB}" },
            RedirectStandardError = true,
            RedirectStandardOutput = true,
            UseShellExecute = false,
        };
        var process = Process.Start(start) ?? throw new InvalidOperationException("socat did not start");
        var pair = new SocatPtyPair(process, pathA, pathB);

        // Process start-up only: the one place real waiting is allowed, bounded by StartupLimit.
        var watch = Stopwatch.StartNew();
        while (!(File.Exists(pathA) && File.Exists(pathB)))
        {
            if (process.HasExited || watch.Elapsed > StartupLimit)
            {
                var error = process.HasExited ? await process.StandardError.ReadToEndAsync() : "(still running)";
                pair.Dispose();
                throw new InvalidOperationException($"socat did not create {pathA} and {pathB} within {StartupLimit.TotalSeconds} s: {error}");
            }

            await Task.Delay(20);
        }

        return pair;
    }

    /// <summary>
    /// Kills socat: both pseudo-terminals vanish, like an unplugged USB adapter, and so do their links, as the device
    /// node of an unplugged adapter does (a killed socat leaves them dangling, pointing at pty numbers others may reuse).
    /// </summary>
    public void Kill()
    {
        if (!_socat.HasExited)
        {
            _socat.Kill(entireProcessTree: true);
            _socat.WaitForExit();
        }

        File.Delete(PathA);
        File.Delete(PathB);
    }

    public void Dispose()
    {
        Kill();
        _socat.Dispose();
    }

    private static string? FindSocat() =>
        (Environment.GetEnvironmentVariable("PATH") ?? "")
            .Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries)
            .Select(dir => Path.Combine(dir, "socat"))
            .FirstOrDefault(File.Exists);
}
