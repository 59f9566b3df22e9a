using System.Text.Json;
using OperatorPanel.TestKit;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// <c>opanel stop</c>: nothing without --yes; against the in-process demo PLC (its handler generated with STOP) and
/// against <c>opanel simulate</c> on a socat pty, with and without STOP in the handler.
/// </summary>
[Collection(RealTimeSerialCollection.Name)]
public sealed class StopCommandTests
{
    [Fact]
    public void Stop_WithoutYes_SaysWhatItWouldDoSendsNothingAndExitsFour()
    {
        var run = CliRunner.Run("stop", "--demo", "--station", "3");

        run.ExitCode.Should().Be(4);
        run.Out.Should().BeEmpty();
        run.Error.Should().Be(
            "opanel: this would put station 3 on demo into STOP: its program stops, the line stops, and its port returns to PPI until "
            + "someone sets RUN. Nothing sent; to do it, give the same command with --yes" + Environment.NewLine);
    }

    [Fact]
    public void Stop_DemoWithYes_StopsAndConfirmsBySilence()
    {
        var run = CliRunner.Run("stop", "--demo", "--yes");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Be("station 2 stopped: the port speaks PPI until someone sets RUN" + Environment.NewLine);
    }

    [Fact]
    public void Stop_DemoReferenceModelJson_GivesStationPortOutcomeAndMessage()
    {
        var run = CliRunner.Run("stop", "--demo", "--yes", "--json", "--model", "reference");

        using var json = JsonDocument.Parse(run.Out);
        json.RootElement.GetProperty("station").GetInt32().Should().Be(2);
        json.RootElement.GetProperty("port").GetString().Should().Be("demo");
        json.RootElement.GetProperty("outcome").GetString().Should().Be("stopped");
        json.RootElement.TryGetProperty("exitCode", out _).Should().BeFalse();
    }

    [Fact]
    public void Stop_SampleProjectOnTheDemoLine_StopsItsStation()
    {
        var run = CliRunner.Run("stop", "--project", Sample, "--demo", "--yes");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Be("station 2 stopped: the port speaks PPI until someone sets RUN" + Environment.NewLine);
    }

    [Fact]
    public void Stop_ProjectWithoutAllowStop_RefusesBeforeSendingAndExitsOne()
    {
        var project = Path.Combine(Path.GetTempPath(), $"opanel-nostop-{Guid.NewGuid():N}.opproj");
        File.WriteAllText(project, File.ReadAllText(Sample).Replace("\"allowStop\": true", "\"allowStop\": false", StringComparison.Ordinal));
        try
        {
            var run = CliRunner.Run("stop", "--project", project, "--demo", "--yes");

            run.ExitCode.Should().Be(1);
            run.Out.Should().BeEmpty();
            run.Error.Should().Be($"opanel: the project does not allow STOP for Filler (station 2): set \"allowStop\": true for it in {project}, "
                + "generate the PLC code again and download it; nothing sent" + Environment.NewLine);
        }
        finally
        {
            File.Delete(project);
        }
    }

    [Fact]
    public void Stop_MissingDevice_NothingSentExitsTwo()
    {
        var run = CliRunner.Run("stop", "--yes", "--device", "/dev/opanel-no-such-port");

        run.ExitCode.Should().Be(2);
        run.Out.Should().StartWith("station 2: STOP not sent: ").And.Contain("/dev/opanel-no-such-port");
    }

    [Fact]
    public async Task Stop_SimulatedPlcOnAPty_StopsItAndItAnswersNothingAfterwards()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var simulator = await SimulateAsync(pty, seconds: 8, "--allow-stop");

        var stop = CliRunner.Run(["stop", "--station", "3", "--yes", "--device", pty.PathB, "--scan-ms", "1000"]);
        var identify = CliRunner.Run(["identify", "--station", "3", "--device", pty.PathB]);

        stop.ExitCode.Should().Be(0, stop.Out + stop.Error);
        stop.Out.Should().Be("station 3 stopped: the port speaks PPI until someone sets RUN" + Environment.NewLine);
        identify.ExitCode.Should().Be(2, "a CPU in STOP answers no Freeport frame");
        (await simulator).Should().Be(0);
    }

    [Fact]
    public async Task Stop_SimulatedHandlerWithoutStop_SendsNoStopAndSaysHowToEnableIt()
    {
        using var pty = await SocatPtyPair.StartAsync();
        var simulator = await SimulateAsync(pty, seconds: 4);

        var stop = CliRunner.Run(["stop", "--station", "3", "--yes", "--device", pty.PathB, "--scan-ms", "1000"]);
        var identify = CliRunner.Run(["identify", "--station", "3", "--device", pty.PathB, "--scan-ms", "1000"]);

        stop.ExitCode.Should().Be(1, stop.Out + stop.Error);
        stop.Out.Should().Contain("station 3: its handler was generated without STOP (IDENTIFY FEATURES bit 0 is 0), nothing sent")
            .And.Contain("\"allowStop\": true").And.Contain("opanel generate --allow-stop");
        identify.ExitCode.Should().Be(0, "the PLC keeps running");
        identify.Out.Should().Contain("STOP          not in the handler");
        (await simulator).Should().Be(0);
    }

    private static string Sample
    {
        get
        {
            for (var folder = new DirectoryInfo(AppContext.BaseDirectory); folder is not null; folder = folder.Parent)
            {
                var candidate = Path.Combine(folder.FullName, "samples", "bottling-line.opproj");
                if (File.Exists(candidate))
                {
                    return candidate;
                }
            }

            throw new FileNotFoundException("samples/bottling-line.opproj not found");
        }
    }

    /// <summary>Starts <c>opanel simulate</c> for station 3 on the pty's A end and returns once it serves (a bounded real wait: process start-up).</summary>
    private static async Task<Task<int>> SimulateAsync(SocatPtyPair pty, int seconds, params string[] extra)
    {
        string[] args = ["simulate", "--cpu", "224", "--station", "3", "--device", pty.PathA, "--duration", $"{seconds}", "--no-process", .. extra,
            "--log-dir", Path.Combine(Path.GetTempPath(), "opanel-tests-logs")];
        var output = new SignalledWriter("simulating");
        var simulator = Task.Run(() => OpanelApp.Run(args, output, TextWriter.Null));
        (await Task.WhenAny(output.Seen, simulator, Task.Delay(TimeSpan.FromSeconds(3)))).Should().BeSameAs(output.Seen, "the simulator should have started");
        return simulator;
    }

    /// <summary>Completes <see cref="Seen"/> once a written line contains the expected text.</summary>
    private sealed class SignalledWriter(string expected) : StringWriter
    {
        private readonly TaskCompletionSource _seen = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public Task Seen => _seen.Task;

        public override void WriteLine(string? value)
        {
            if (value?.Contains(expected, StringComparison.Ordinal) == true)
            {
                _seen.TrySetResult();
            }
        }
    }
}
