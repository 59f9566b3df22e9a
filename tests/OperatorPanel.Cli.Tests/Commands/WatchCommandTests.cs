using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// <c>opanel watch</c> on the sample line with the in-process demo line (real time: a refresh or two, well under a
/// second). The demo process starts 2 s in: the line runs, bottles are counted and alarm M2.2 is on, since a shift starts
/// with the tank low and the pump refilling it (it stays on for some 14 s; DemoField, DemoProgram.Alarms).
/// </summary>
public sealed class WatchCommandTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-watch-tests-" + Guid.NewGuid().ToString("N"));

    public WatchCommandTests() => Directory.CreateDirectory(_folder);

    private static string Sample => Path.Combine(RepositoryRoot(), "samples", "bottling-line.opproj");

    [Theory]
    [InlineData("stl")]
    [InlineData("reference")]
    public void Watch_DemoOnce_ShowsStationOnlineLampsTagsAndAlarms(string model)
    {
        var run = CliRunner.Run("watch", Sample, "--demo", "--once", "--model", model);

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().StartWith("Bottling line 1  (continuous, at least 100 ms apart)  cycle 1  ")
            .And.Contain("Filler  station 2  CPU 224  COM3 (demo) 9600 8N1  online")
            .And.Contain("Low product level in tank");
        // Real time: a loaded machine may cost a retry, so the counters are checked for shape, not for zero.
        run.Out.Should().MatchRegex(@"link     requests \d+  replies [1-9]\d*  retries \d+  timeouts \d+  rtt avg \d+\.\d ms");
        run.Out.Should().MatchRegex(@"    IB0   ●[●○]{7}  I0\.0 EStopHealthy  I0\.1 StartButton"); // e-stop chain healthy in the demo
        run.Out.Should().MatchRegex(@"    QB1   [●○]{2}······  Q1\.0 Horn  Q1\.1 RejectPusher");
        run.Out.Should().MatchRegex(@"    BottleCount      VD100 +[1-9]\d* bottles  good"); // the 2 s warm-up counts a bottle or two
        run.Out.Should().MatchRegex(@"    FillSetpoint     VD120 +\d+(\.\d+)? ml  good"); // REAL shown as a number
        run.Out.Should().MatchRegex(@"    StatusWord       MW10 +2#\d{4}_\d{4}_\d{4}_\d{4}  good");
        run.Out.Should().MatchRegex(@"    M2\.2 +warning +Low product level in tank");
    }

    [Fact]
    public void Watch_DemoPpiBus_ReadsTheCpusWithoutHandlerAndShowsPpi()
    {
        var file = Path.Combine(_folder, "ppi.opproj");
        File.WriteAllText(file, File.ReadAllText(Sample)
            .Replace("\"parity\": \"none\"", "\"parity\": \"even\"", StringComparison.Ordinal)
            .Replace("\"kind\": \"cable\"", "\"kind\": \"cable\", \"protocol\": \"ppi\"", StringComparison.Ordinal));

        var run = CliRunner.Run("watch", file, "--demo", "--once");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("Filler  station 2  CPU 224  COM3 (demo) 9600 8E1 PPI  online");
        run.Out.Should().MatchRegex(@"link     requests \d+  replies [1-9]\d*  retries \d+  timeouts \d+");
        run.Out.Should().MatchRegex(@"    BottleCount      VD100 +\d+ bottles  good");
        run.Out.Should().MatchRegex(@"    StatusWord       MW10 +2#\d{4}_\d{4}_\d{4}_\d{4}  good");
    }

    [Fact]
    public void Watch_DemoPpiOnFreeportProject_ReadsEveryBusOverPpiAndSaysSo()
    {
        var before = File.ReadAllBytes(Sample);

        var run = CliRunner.Run("watch", Sample, "--demo", "--ppi", "--once");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().StartWith(
            "reading COM3 over PPI at 9600 baud 8E1 (a CPU whose port is set to another PPI rate in its system block will not answer): "
            + "no handler needed, STOP and handler checks are off; the project file is unchanged" + Environment.NewLine + "Bottling line 1  ");
        // The demo CPUs of a PPI bus run no handler: the values come over PPI, not from a Freeport handler.
        run.Out.Should().Contain("Filler  station 2  CPU 224  COM3 (demo) 9600 8E1 PPI  online").And.Contain("handler  no handler (PPI)");
        run.Out.Should().MatchRegex(@"    BottleCount      VD100 +\d+ bottles  good");
        run.Out.Should().MatchRegex(@"    StatusWord       MW10 +2#\d{4}_\d{4}_\d{4}_\d{4}  good");
        File.ReadAllBytes(Sample).Should().Equal(before, "the switch is in memory");
    }

    [Theory]
    [InlineData("--ppi", "--baud", "38400", "--baud 38400 is not a PPI rate; PPI runs at 9600, 19200, 187500")]
    [InlineData("--baud", "19200", "--once", "--baud needs --ppi")]
    public void Watch_PpiBaudWrong_FailsSayingWhy(string first, string second, string third, string message)
    {
        var run = CliRunner.Run("watch", Sample, "--demo", "--once", first, second, third);

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain(message);
    }

    [Fact]
    public void Watch_DemoCyclesJson_PrintsOneObjectPerCycle()
    {
        var run = CliRunner.Run("watch", Sample, "--demo", "--cycles", "2", "--json");

        run.ExitCode.Should().Be(0, run.Error);
        var lines = run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        lines.Should().HaveCount(2);
        for (var i = 0; i < lines.Length; i++)
        {
            using var json = JsonDocument.Parse(lines[i]);
            json.RootElement.GetProperty("cycle").GetInt64().Should().Be(i + 1);
            var station = json.RootElement.GetProperty("stations")[0];
            station.GetProperty("state").GetString().Should().Be("online");
            station.GetProperty("inputs")[0].GetProperty("bits")[0].GetProperty("symbol").GetString().Should().Be("EStopHealthy");
            station.GetProperty("tags").EnumerateArray().Should().Contain(t => t.GetProperty("address").GetString() == "VD100");
        }
    }

    [Fact]
    public void Watch_Demo_IdentifiesTheStationDefinesItsListAndThenPollsItWithReadList()
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        var logs = Path.Combine(_folder, "logs");

        var exit = OpanelApp.Run(["watch", Sample, "--demo", "--cycles", "4", "--log-level", "Verbose", "--log-dir", logs, "--history-dir", Path.Combine(_folder, "history")], output, error);

        exit.Should().Be(0, error.ToString());
        var trace = Directory.GetFiles(logs).SelectMany(File.ReadAllLines).Where(l => l.Contains("OperatorPanel.Core.Link.V3.V3Link", StringComparison.Ordinal)).ToList();
        // Real time: a loaded machine may cost the first IDENTIFY, so any SEQ will do.
        trace.Should().Contain(l => l.Contains("v3 \"Identify\" SEQ", StringComparison.Ordinal) && l.Contains("-> \"Ok\", 24 payload bytes", StringComparison.Ordinal), "the watch identifies first");
        trace.Should().Contain(l => l.Contains("v3 \"DefineList\" SEQ", StringComparison.Ordinal) && l.Contains("-> \"Ok\", 0 payload bytes", StringComparison.Ordinal), "then defines the station's list");
        trace.Should().Contain(l => l.Contains("v3 \"ReadList\" SEQ", StringComparison.Ordinal), "and reads it with one READ LIST a refresh");
    }

    [Fact]
    public void Watch_BadProject_ExitsOneListingTheProblems()
    {
        var file = Path.Combine(_folder, "bad.opproj");
        File.WriteAllText(file, File.ReadAllText(Sample).Replace("\"VD100\"", "\"VD8191\"", StringComparison.Ordinal));

        var run = CliRunner.Run("watch", file, "--demo", "--once");

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain($"{file}: $.stations[0].tags[0].address: VD8191");
        run.Out.Should().BeEmpty();
    }

    [Fact]
    public void Watch_MissingProject_ExitsOne()
    {
        CliRunner.Run("watch", Path.Combine(_folder, "none.opproj"), "--once").ExitCode.Should().Be(1);
    }

    [Fact]
    public void Watch_PortMissingOnce_ShowsOfflineAndExitsTwo()
    {
        var file = Path.Combine(_folder, "line.opproj");
        var port = Path.Combine(_folder, "no-such-port");
        CliRunner.Run("project", "new", "--cpu", "222", "--port", port, "-o", file).ExitCode.Should().Be(0);

        var run = CliRunner.Run("watch", file, "--once");

        run.ExitCode.Should().Be(2);
        run.Out.Should().Contain("offline").And.Contain($"last error: station 2: serial port {port}: open failed").And.NotContain("PortUnavailable");
        run.Out.Should().MatchRegex(@"IB0   \?{8}");
    }

    [Fact]
    public void Watch_PortMissingOnce_ShowsAlarmsUnknownNotNoneActive()
    {
        var file = Path.Combine(_folder, "line.opproj");
        File.WriteAllText(file, File.ReadAllText(Sample).Replace("\"COM3\"", $"\"{Path.Combine(_folder, "no-such-port")}\"", StringComparison.Ordinal));

        var text = CliRunner.Run("watch", file, "--once");
        var json = CliRunner.Run("watch", file, "--once", "--json");

        text.Out.Should().Contain("  alarms   unknown: Filler offline (8 of 8 flags not read)").And.NotContain("none active");
        using var line = JsonDocument.Parse(json.Out);
        var station = line.RootElement.GetProperty("stations")[0];
        station.GetProperty("alarmsUnknown").GetInt32().Should().Be(8);
        station.GetProperty("alarms").EnumerateArray().Select(a => a.GetProperty("state").GetString()).Should().AllBe("unknown").And.HaveCount(8);
    }

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private static string RepositoryRoot()
    {
        var directory = new DirectoryInfo(AppContext.BaseDirectory);
        while (directory is not null && !File.Exists(Path.Combine(directory.FullName, "OperatorPanel.sln")))
        {
            directory = directory.Parent;
        }

        return directory?.FullName ?? throw new InvalidOperationException("OperatorPanel.sln not found above the test folder");
    }
}
