using System.Diagnostics;
using OperatorPanel.TestKit;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// <c>opanel write</c> cut short while a write is on the wire: the program runs as its own process (so it can be
/// signalled and killed) against <c>opanel simulate</c> on a socat pty pair at 1200 baud, where one write takes about
/// half a second. Real time, bounded: the simulation stops itself, and every wait has a limit.
/// SIGTERM stands for Ctrl+C (both take the same path in the program): a test host started in the background may have
/// SIGINT ignored, which its children inherit.
/// </summary>
[Collection(RealTimeSerialCollection.Name)]
public sealed class WriteInterruptTests : IDisposable
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(30);
    private readonly string _logs = Path.Combine(Path.GetTempPath(), "opanel-interrupt-" + Guid.NewGuid().ToString("N"));

    public void Dispose()
    {
        if (Directory.Exists(_logs))
        {
            Directory.Delete(_logs, recursive: true);
        }
    }

    [Fact]
    public async Task Write_InterruptedDuringTheFirstWrite_FinishesItPrintsEveryOutcomeAndExits130()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var simulator = Simulate(pty.PathA);

        using var write = StartOpanel("write", "VD300=999", "VW200=2", "VB100=7", "MW10=5", "--device", pty.PathB, "--baud", "1200", "--scan-ms", "1000", "--log-dir", _logs);
        await WaitForAsync(() => Journal().Any(l => l.Contains("\"step\":\"intent\"", StringComparison.Ordinal)));
        Signal(write, "TERM");
        var (exit, output, error) = await FinishAsync(write);

        exit.Should().Be(130, error);
        var lines = output.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        lines.Should().HaveCount(4, "every write is printed: done, or not sent");
        // Finished and read back: "confirmed" (or "confirmed (reply lost, read back)"); on a test host so loaded that the
        // real-time simulator lost the frame, "not applied" as the read-back proved. Either way what it printed is what
        // the PLC holds, which the read at the end checks.
        var applied = lines[0].StartsWith("VD300    0 -> 999  confirmed", StringComparison.Ordinal);
        if (!applied)
        {
            lines[0].Should().StartWith("VD300    0 -> 999  not applied", "the write on the wire was finished and read back (all it printed: {0})", output)
                .And.Contain("the PLC still holds 0");
        }

        lines.Should().Contain(l => l.EndsWith("not sent: interrupted (Ctrl+C) before it was sent", StringComparison.Ordinal));
        error.Should().Contain("opanel: stopping after the write on the wire");
        var journal = Journal();
        var sent = lines.Count(l => !l.Contains("not sent", StringComparison.Ordinal));
        journal.Count(l => l.Contains("\"step\":\"intent\"", StringComparison.Ordinal)).Should().Be(sent, "each write sent has its intent on record");
        journal.Count(l => l.Contains("\"step\":\"outcome\"", StringComparison.Ordinal)).Should().Be(sent, "and its outcome");

        var read = Read("VD300", "VB100", "--device", pty.PathB);
        read.Out.Should().StartWith(applied ? "VD300    999 " : "VD300    0 ", "the PLC holds what the write printed").And.Contain("VB100    0 ", "a write not sent is not in the PLC");
        await EndAsync(pty, simulator);
    }

    [Fact]
    public async Task Write_KilledWithItsWriteOnTheWire_NextStartSettlesItByReadingBack()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var simulator = Simulate(pty.PathA);

        using var write = StartOpanel("write", "VD300=999", "--device", pty.PathB, "--baud", "1200", "--scan-ms", "1000", "--log-dir", _logs);
        await WaitForAsync(() => Journal().Any(l => l.Contains("\"step\":\"intent\"", StringComparison.Ordinal)));
        write.Kill();
        await write.WaitForExitAsync().WaitAsync(Limit);
        Journal().Should().NotContain(l => l.Contains("\"step\":\"outcome\"", StringComparison.Ordinal), "killed at once, with half a second on the wire ahead");

        var read = Read("VD300", "--device", pty.PathB);

        read.ExitCode.Should().Be(0, read.Error);
        var applied = read.Out.StartsWith("VD300    999 ", StringComparison.Ordinal);
        read.Error.Should().Contain("opanel: a write cut short earlier (its program ended before the outcome): station 2 VD300: 16#00000000 -> 16#000003E7 by ")
            .And.Contain(applied ? "resolved at start: applied: the PLC holds the requested 16#000003E7" : "resolved at start: not applied: the PLC still holds the old 16#00000000");
        Journal().Should().Contain(l => l.Contains("\"step\":\"resolvedAtStart\"", StringComparison.Ordinal));
        await EndAsync(pty, simulator);
    }

    /// <summary>The simulated PLC ends when its device goes with socat (or after 60 s at the latest).</summary>
    private static async Task EndAsync(SocatPtyPair pty, Task<int> simulator)
    {
        pty.Kill();
        await simulator.WaitAsync(Limit);
    }

    private Task<int> Simulate(string device)
    {
        string[] args = ["simulate", "--cpu", "224", "--station", "2", "--device", device, "--baud", "1200", "--duration", "60", "--log-dir", _logs];
        return Task.Run(() => OpanelApp.Run(args, TextWriter.Null, TextWriter.Null));
    }

    /// <summary>opanel read in-process, with this test's log folder (and so its write journal).</summary>
    private (int ExitCode, string Out, string Error) Read(params string[] args)
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        var exit = OpanelApp.Run(["read", .. args, "--baud", "1200", "--scan-ms", "1000", "--log-dir", _logs], output, error);
        return (exit, output.ToString(), error.ToString());
    }

    private List<string> Journal()
    {
        var path = Path.Combine(_logs, "write-journal.jsonl");
        try
        {
            return File.Exists(path) ? [.. File.ReadAllLines(path)] : [];
        }
        catch (IOException)
        {
            return []; // being appended to right now
        }
    }

    private static Process StartOpanel(params string[] args)
    {
        var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add(typeof(OpanelApp).Assembly.Location);
        foreach (var arg in args)
        {
            start.ArgumentList.Add(arg);
        }

        return Process.Start(start) ?? throw new InvalidOperationException("opanel did not start");
    }

    private static void Signal(Process process, string signal)
    {
        using var kill = Process.Start(new ProcessStartInfo("kill") { ArgumentList = { "-" + signal, process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture) }, UseShellExecute = false })!;
        kill.WaitForExit();
    }

    private static async Task<(int Exit, string Out, string Error)> FinishAsync(Process process)
    {
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEndAsync();
        await process.WaitForExitAsync().WaitAsync(Limit);
        return (process.ExitCode, await output, await error);
    }

    /// <summary>Process start-up and a serial line in real time: polled, bounded by <see cref="Limit"/>.</summary>
    private static async Task WaitForAsync(Func<bool> condition)
    {
        var watch = Stopwatch.StartNew();
        while (!condition())
        {
            if (watch.Elapsed > Limit)
            {
                throw new TimeoutException("opanel did not get there in time");
            }

            await Task.Delay(10);
        }
    }
}
