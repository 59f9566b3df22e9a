using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Bench;

/// <summary>`opanel bench link` in-process; the measured part runs over a real socat pty (few cycles), so its numbers vary and are not asserted.</summary>
public sealed class BenchCommandTests
{
    [Fact]
    public void BenchLink_Text_LabelsModelAndMeasurementAndEndsWithTheSummaryLine()
    {
        var (exit, output, error) = CliRunner.Run("bench", "link", "--cycles", "2");

        exit.Should().Be(0, $"stderr: {error}");
        output.Should().Contain("Reference line: CPU 226 (Current), station 2")
            .And.Contain("alarms      64  M10.0-M17.7")
            .And.Contain("Time model (MODELLED, not measured): PC/PPI cable, 9600 8N1")
            .And.Contain("steady (every value read in full)")
            .And.Contain("idle (nothing changed)")
            .And.Contain("MEASURED round trip over a socat pty")
            .And.Contain("Goals for the reference line")
            .And.MatchRegex(@"  (met    |NOT MET) steady refresh 9600 8N1");
        output.Should().NotContainAny(["issue", "paper", "seed", "PASS", "FAIL"], "benchmark output speaks of goals, not of how the project is run");
        var lines = output.TrimEnd().Split('\n');
        lines[^1].Should().MatchRegex(@"^bench link: steady \d+ chars, \d+\.\d ms, \d+\.\d\d x hex bound; idle \d+ chars, \d+\.\d ms$");
        lines.Count(l => l.StartsWith("bench link:", StringComparison.Ordinal)).Should().Be(1);
    }

    [Fact]
    public void BenchLink_Radio_ModelsTheRadioModulesAndTakesLongerThanTheCable()
    {
        var (_, cable, _) = CliRunner.Run("bench", "link", "--cycles", "1", "--json");
        var (exit, radio, error) = CliRunner.Run("bench", "link", "--cycles", "1", "--json", "--radio");

        exit.Should().Be(0, $"stderr: {error}");
        var cableModel = JsonDocument.Parse(cable).RootElement.GetProperty("modelled");
        var radioModel = JsonDocument.Parse(radio).RootElement.GetProperty("modelled");
        radioModel.GetProperty("medium").GetString().Should().Be("radio modules");
        radioModel.GetProperty("steady").GetProperty("chars").GetInt32().Should().Be(cableModel.GetProperty("steady").GetProperty("chars").GetInt32());
        radioModel.GetProperty("steady").GetProperty("ms").GetDouble().Should().BeGreaterThan(cableModel.GetProperty("steady").GetProperty("ms").GetDouble());
        radioModel.GetProperty("summary").GetString().Should().StartWith("bench link: steady ");
    }

    [Fact]
    public void BenchLink_Json_GivesRowsTargetsTheModelAndTheMeasurement()
    {
        var (exit, output, error) = CliRunner.Run("bench", "link", "--cycles", "2", "--json");

        exit.Should().Be(0, $"stdout: {output} stderr: {error}");
        using var json = JsonDocument.Parse(output);
        var root = json.RootElement;
        root.GetProperty("rows").GetArrayLength().Should().Be(7);
        root.GetProperty("targets").EnumerateArray().Select(t => t.GetProperty("verdict").GetString())
            .Should().HaveCount(3).And.OnlyContain(v => v == "met" || v == "NOT MET");
        root.GetProperty("modelled").GetProperty("steady").GetProperty("exchanges").GetArrayLength().Should().BePositive();
        root.GetProperty("measured").GetProperty("cycles").GetInt32().Should().Be(2);
        root.GetProperty("measured").GetProperty("exchangeAverageMs").GetDouble().Should().BePositive();
    }

    [Theory]
    [InlineData("--scan-ms", "-1")]
    [InlineData("--air-baud", "100")]
    public void BenchLink_BadModelOption_FailsAsBadInputNamingIt(string option, string value)
    {
        var (exit, _, error) = CliRunner.Run("bench", "link", "--cycles", "1", option, value);

        exit.Should().Be(1);
        error.Should().Contain($"{option} {value}");
    }

    [Fact]
    public void BenchPlan_SmallCounts_PrintsOneRowPerCount()
    {
        var (exit, output, error) = CliRunner.Run("bench", "plan", "--tags", "20", "50", "--runs", "1");

        exit.Should().Be(0, $"stderr: {error}");
        output.Should().Contain("PollPlanner.Build on one CPU 226 station").And.MatchRegex(@"\n\s+20\s+1\s").And.MatchRegex(@"\n\s+50\s+1\s");
    }

    [Fact]
    public void BenchLink_ZeroCycles_FailsAsBadInput()
    {
        var (exit, _, error) = CliRunner.Run("bench", "link", "--cycles", "0");

        exit.Should().Be(1);
        error.Should().Contain("--cycles 0");
    }

    [Fact]
    public void BenchLink_Protocol3_PartsGoalsAndTheBytesSummaryLineLast()
    {
        var (exit, output, error) = CliRunner.Run("bench", "link", "--protocol", "3");

        exit.Should().Be(0, $"stderr: {error}");
        output.Should().Contain("one DEFINE LIST of 32 slots, 76 data bytes")
            .And.Contain("READ LIST FULL (steady: the whole list): 8 + 85 bytes")
            .And.Contain("READ LIST (idle: UNCHANGED): 8 + 9 bytes")
            .And.Contain("binary bound: 74 bytes")
            .And.MatchRegex(@"steady <= 1\.5 x binary bound = 115\.6 ms: \d+\.\d ms, (met|NOT MET)");
        output.Should().NotContain("NOTE");
        var lines = output.TrimEnd().Split('\n');
        lines[^1].Should().MatchRegex(@"^bench link: steady 93 bytes, \d+\.\d ms, \d+\.\d\d x binary bound; idle 17 bytes, \d+\.\d ms$");
    }

    [Fact]
    public void BenchLink_Protocol3RadioLongScan_SaysTheModuleDropsRepliesPausedOverTheEndTimer()
    {
        var (exit, output, _) = CliRunner.Run("bench", "link", "--protocol", "3", "--radio", "--scan-ms", "10");

        exit.Should().Be(0);
        output.Should().Contain("each module forwards a frame once Core's Reader has it whole by its LEN")
            .And.Contain("NOTE READ LIST FULL (steady: the whole list): the PLC module dropped the reply")
            .And.NotContain("NOTE READ LIST (idle: UNCHANGED)", "a reply without payload leaves in one XMT, without a pause");
    }

    [Fact]
    public void BenchLink_Protocol3WithPpi_Refused()
    {
        var (exit, _, error) = CliRunner.Run("bench", "link", "--protocol", "3", "--ppi");

        exit.Should().Be(1);
        error.Should().Contain("--protocol 3 and --ppi");
    }
}
