using System.Text.Json;
using System.Text.RegularExpressions;
using OperatorPanel.Historian;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// <c>opanel watch --demo</c> records into the demo line's history from the first cycle; <c>opanel history</c> prints it
/// as text, CSV or JSON; <c>opanel trend</c> draws it. Each test has its own history folder.
/// </summary>
public sealed class HistoryCommandTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-history-cli-" + Guid.NewGuid().ToString("N"));

    public HistoryCommandTests() => Directory.CreateDirectory(_folder);

    private string History => Path.Combine(_folder, "history");

    private static string Sample => Path.Combine(RepositoryRoot(), "samples", "bottling-line.opproj");

    [Fact]
    public void History_AfterADemoWatch_PrintsTheRecordedValuesFromTheFirstCycle()
    {
        var watch = CliRunner.Run("watch", Sample, "--demo", "--cycles", "3", "--history-dir", History);
        watch.ExitCode.Should().Be(0, watch.Error);
        watch.Out.Should().MatchRegex(@"history: [1-9]\d* rows recorded into .*-demo\.history\.db");

        var run = CliRunner.Run("history", "TankLevel", "Filler.BottleCount", "I0.0", "--project", Sample, "--demo", "--history-dir", History);

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().StartWith("Bottling line 1: history from ");
        run.Out.Should().MatchRegex(@"Filler\.TankLevel +- +bad", "the first row is the value before the first reply: not read yet");
        run.Out.Should().MatchRegex(@"Filler\.TankLevel +\d+\.\d %  good", "in the tag's engineering units: raw 0..1000 is 0..100 %");
        run.Out.Should().MatchRegex(@"Filler\.BottleCount +[1-9]\d* bottles +good");
        run.Out.Should().MatchRegex(@"Filler\.EStopHealthy +1 +good");
    }

    [Fact]
    public void History_Json_HasEachTagWithItsSamples()
    {
        CliRunner.Run("watch", Sample, "--demo", "--cycles", "2", "--history-dir", History).ExitCode.Should().Be(0);

        var run = CliRunner.Run("history", "FillSetpoint", "--project", Sample, "--demo", "--since", "1h", "--json", "--history-dir", History);

        run.ExitCode.Should().Be(0, run.Error);
        using var json = JsonDocument.Parse(run.Out);
        var tag = json.RootElement.GetProperty("tags")[0];
        tag.GetProperty("symbol").GetString().Should().Be("FillSetpoint");
        tag.GetProperty("format").GetString().Should().Be("Float");
        tag.GetProperty("samples").EnumerateArray().Should().Contain(s => s.GetProperty("quality").GetString() == "good" && s.GetProperty("number").GetDouble() > 0);
    }

    [Fact]
    public void History_Csv_HasAHeaderAndIsoTimes()
    {
        CliRunner.Run("watch", Sample, "--demo", "--cycles", "2", "--history-dir", History).ExitCode.Should().Be(0);

        var run = CliRunner.Run("history", "LineSpeed", "--project", Sample, "--demo", "--csv", "--history-dir", History);

        run.Out.Should().StartWith("Time,Station,Symbol,Address,Value,Number,Quality\r\n");
        run.Out.Should().MatchRegex(@"\r\n\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z,Filler,LineSpeed,VW140,\d+ bottles/min,\d+,good\r\n", "the value as the panel shows it, with its unit, and its number");
    }

    [Fact]
    public void History_NothingRecordedYet_SaysSoAndExitsZero()
    {
        var run = CliRunner.Run("history", "--project", Sample, "--history-dir", History);

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("nothing recorded yet").And.Contain(".history.db does not exist");
    }

    [Theory]
    [InlineData("NoSuchTag", "'NoSuchTag': no recorded input, output or tag of that name or address in the project")]
    [InlineData("--since", "--since '2x': give a number and a unit, e.g. 90s, 30m, 2h or 7d")]
    public void History_BadInput_ExitsOneNamingIt(string what, string message)
    {
        string[] args = what == "--since"
            ? ["history", "--project", Sample, "--since", "2x", "--history-dir", History]
            : ["history", what, "--project", Sample, "--history-dir", History];

        var run = CliRunner.Run(args);

        run.ExitCode.Should().Be(1);
        run.Error.Should().Contain(message);
    }

    [Fact]
    public void Trend_DemoPiped_PrintsEachTagsChartAtTheEnd()
    {
        var run = CliRunner.Run("trend", "TankLevel", "LineSpeed", "--project", Sample, "--demo", "--duration", "3", "--span", "1m", "--width", "40", "--history-dir", History);

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("Filler.TankLevel").And.Contain("Filler.LineSpeed");
        run.Out.Should().MatchRegex(@"range -?\d+ \.\. -?\d+");
        run.Out.Should().MatchRegex("[▁▂▃▄▅▆▇█]", "the values were drawn");
    }

    [Theory]
    [InlineData("random", "not a history database")]
    [InlineData("truncated", "damaged")]
    public void Trend_HistoryDatabaseDamaged_ExitsTwoWithAPlainMessageAndNoStackTrace(string damage, string reason)
    {
        var database = new HistoryFolder(History).DatabaseFor(Sample, demo: true);
        if (damage == "random")
        {
            Directory.CreateDirectory(History);
            File.WriteAllBytes(database, [.. Enumerable.Range(0, 8192).Select(i => (byte)((i * 73) + 11))]);
        }
        else
        {
            CliRunner.Run("watch", Sample, "--demo", "--cycles", "2", "--history-dir", History).ExitCode.Should().Be(0);
            using (var file = File.OpenWrite(database))
            {
                file.SetLength(8192);
            }

            File.Delete(database + "-wal");
            File.Delete(database + "-shm");
        }

        var run = CliRunner.Run("trend", "TankLevel", "--project", Sample, "--demo", "--duration", "2", "--history-dir", History);

        run.ExitCode.Should().Be(2, "trend's help: 2 when the history could not be read or recorded");
        run.Error.Should().StartWith("opanel: no trend drawn").And.Contain($"The history database {database}: the file is {reason}")
            .And.NotContain("Unhandled").And.NotContain("Exception").And.NotContain("   at ");
    }

    [Fact]
    public void Trend_PortMissing_NamesThePortFailureAndShowsNoMadeUpRange()
    {
        var port = Path.Combine(_folder, "no-such-port");
        var project = Path.Combine(_folder, "line.opproj");
        File.WriteAllText(project, File.ReadAllText(Sample).Replace("\"COM3\"", $"\"{port}\"", StringComparison.Ordinal));
        var failure = $"Filler offline, last error: station 2: serial port {port}: open failed";

        var text = CliRunner.Run("trend", "TankLevel", "--project", project, "--duration", "1", "--width", "120", "--history-dir", History);
        var json = CliRunner.Run("trend", "TankLevel", "--project", project, "--duration", "2", "--json", "--history-dir", History);

        text.ExitCode.Should().Be(2);
        text.Error.Should().StartWith($"opanel: {failure}");
        // The console is as wide as the chart: a longer line wraps at a space.
        Regex.Replace(text.Out, @"\s+", " ").Should().Contain(failure, "the chart says why it is empty")
            .And.Contain("range none: no good value recorded in the window").And.NotContain("range 0 .. 0");
        json.ExitCode.Should().Be(2);
        var lines = json.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => JsonDocument.Parse(l).RootElement).ToList();
        var frame = lines[0];
        frame.GetProperty("stations")[0].GetProperty("state").GetString().Should().Be("offline");
        frame.GetProperty("stations")[0].GetProperty("lastError").GetString().Should().StartWith($"station 2: serial port {port}: open failed");
        var tag = frame.GetProperty("tags")[0];
        (tag.GetProperty("min").ValueKind, tag.GetProperty("max").ValueKind).Should().Be((JsonValueKind.Null, JsonValueKind.Null));
        lines[^1].GetProperty("ok").GetBoolean().Should().BeFalse();
        lines[^1].GetProperty("error").GetString().Should().StartWith(failure);
    }

    [Fact]
    public void BenchHistory_SmallRun_PrintsBothStreamsAndTheGoals()
    {
        var run = CliRunner.Run("bench", "history", "--tags", "20", "--hours", "0.02", "--project", Sample);

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("demo line").And.Contain("20 tags at 1 s").And.MatchRegex(@"insert rate .*: \d+ rows/s");
        run.Out.Should().MatchRegex(@"goals for 20 tags at 1 s: cpu \d+\.\d\d % < 5 % of a core (met|NOT MET); growth \d+\.\d MB/day < 100 MB (met|NOT MET)");
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
