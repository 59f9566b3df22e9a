using System.Runtime.CompilerServices;
using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary><c>opanel stl run</c> on the corpus programs (tests/StlCorpus) and on programs it must refuse.</summary>
public sealed class StlRunCommandTests
{
    private static string Corpus(string name, [CallerFilePath] string self = "") =>
        Path.GetFullPath(Path.Combine(Path.GetDirectoryName(self)!, "..", "..", "StlCorpus", name));

    [Fact]
    public void Run_TimerProgram_PrintsEachAddressAndValueAndExitsZero()
    {
        var (exit, output, error) = CliRunner.Run("stl", "run", Corpus("TimerOnDelay.awl"), "--cpu", "224", "--for", "1.5s",
            "--set", "I0.0=1", "--print", "T37", "--print", "T37.bit", "--print", "Q0.0", "--print", "VW0");

        exit.Should().Be(0, error);
        output.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries).Should().Equal("T37 14", "T37.BIT 1", "Q0.0 1", "VW0 14");
    }

    [Fact]
    public void Run_TimedSettings_AppliedAtTheirSimulatedTimes()
    {
        var (exit, output, _) = CliRunner.Run("stl", "run", Corpus("TimerOffDelay.awl"), "--cpu", "226", "--for", "3s",
            "--set", "I0.0=1@1s", "--set", "I0.0=0@2s", "--print", "T38", "--print", "Q0.0");

        exit.Should().Be(0);
        output.Should().Be($"T38 9{Environment.NewLine}Q0.0 1{Environment.NewLine}");
    }

    [Fact]
    public void Run_Json_GivesValuesScansAndMode()
    {
        var (exit, output, _) = CliRunner.Run("stl", "run", Corpus("RealMath.awl"), "--cpu", "224XP", "--for", "100ms",
            "--print", "VD0:real", "--print", "C5", "--json");

        exit.Should().Be(0);
        using var json = JsonDocument.Parse(output);
        json.RootElement.GetProperty("mode").GetString().Should().Be("Run");
        json.RootElement.GetProperty("scans").GetInt64().Should().BePositive();
        var values = json.RootElement.GetProperty("values").EnumerateArray().Select(v => (v.GetProperty("address").GetString(), v.GetProperty("value").GetDouble()));
        values.Should().Equal(("VD0:REAL", 12.5), ("C5", 0));
    }

    [Fact]
    public void Run_UnimplementedInstructions_ExitOneWithFileAndLineForEach()
    {
        var (exit, output, error) = CliRunner.Run("stl", "run", Corpus("Refused.awl"), "--cpu", "224", "--print", "Q0.0");

        exit.Should().Be(1);
        output.Should().BeEmpty();
        error.Should().Contain("Refused.awl:10: PID is not implemented").And.Contain("Refused.awl:12: NETW is not implemented");
    }

    [Fact]
    public void Run_HighSpeedCounter_WarnsByLineAndRunsTheRest()
    {
        var (exit, output, error) = CliRunner.Run("stl", "run", Corpus("HighSpeedCounter.awl"), "--cpu", "224", "--for", "1.5s",
            "--set", "I0.0=1", "--print", "Q0.1");

        exit.Should().Be(0, error);
        output.Should().Be($"Q0.1 1{Environment.NewLine}");
        error.Should().Contain("HighSpeedCounter.awl:11: warning: HSC: high-speed counters")
            .And.Contain("HighSpeedCounter.awl:9: warning: ATCH: event 12 (HSC0 CV=PV) never fires in the simulator");
    }

    [Fact]
    public void Run_HighSpeedCounterStrict_ExitOneNamingEach()
    {
        var (exit, _, error) = CliRunner.Run("stl", "run", Corpus("HighSpeedCounter.awl"), "--cpu", "224", "--strict", "--print", "Q0.1");

        exit.Should().Be(1);
        error.Should().Contain("HighSpeedCounter.awl:8: HDEF is not implemented by the simulator").And.Contain("(--strict)");
    }

    [Fact]
    public void Run_StopInstruction_ReportsTheStopAndStillPrints()
    {
        var (exit, output, error) = CliRunner.Run("stl", "run", Corpus("StopWdr.awl"), "--cpu", "222", "--for", "1s",
            "--set", "I0.7=1@0.5s", "--print", "Q0.0");

        exit.Should().Be(0);
        output.Should().Be($"Q0.0 0{Environment.NewLine}");
        error.Should().Contain("StopWdr.awl:").And.Contain("went to STOP (Stop");
    }

    [Theory]
    [InlineData("--print", "T300", "0-255")]
    [InlineData("--print", "VB9000", "VB9000")]
    [InlineData("--print", "VW0.bit", ".bit is for timers")]
    [InlineData("--set", "I0.0=2", "does not fit a bit")]
    [InlineData("--set", "SMB0=1", "written by the CPU")]
    [InlineData("--set", "I0.0=1@soon", "not a time")]
    [InlineData("--for", "forever", "not a time")]
    public void Run_BadOption_ExitOneNamingIt(string option, string value, string reason)
    {
        var (exit, _, error) = CliRunner.Run("stl", "run", Corpus("Counters.awl"), "--cpu", "221", option, value);

        exit.Should().Be(1);
        error.Should().Contain(reason);
    }

    [Fact]
    public void Run_SetAfterFor_ExitOneNamingTheSetting()
    {
        var (exit, output, error) = CliRunner.Run("stl", "run", Corpus("Counters.awl"), "--cpu", "224", "--for", "2s",
            "--set", "I0.0=1@3s", "--print", "C0");

        exit.Should().Be(1);
        output.Should().BeEmpty();
        error.Should().Contain("--set 'I0.0=1@3s'").And.Contain("after --for 2s");
    }

    [Fact]
    public void Run_ForInMinutes_RunsAndPrintsTheLastCompleteScan()
    {
        var (exit, output, error) = CliRunner.Run("stl", "run", Corpus("ScanEnd.awl"), "--cpu", "224", "--for", "0.01m",
            "--print", "Q0.6", "--print", "VW2", "--print", "VW0");

        exit.Should().Be(0, error);
        output.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries).Should().Equal("Q0.6 1", "VW2 10", "VW0 11");
    }

    [Fact]
    public void Run_Json_SaysWhenTheStateWasTaken()
    {
        var (exit, output, _) = CliRunner.Run("stl", "run", Corpus("ScanEnd.awl"), "--cpu", "224", "--for", "50ms", "--print", "Q0.6", "--json");

        exit.Should().Be(0);
        using var json = JsonDocument.Parse(output);
        var at = json.RootElement.GetProperty("stateAtMs").GetDouble();
        at.Should().BeInRange(45, 50, "the end of the last scan before 50 ms (a scan takes about 1.4 ms)");
        json.RootElement.GetProperty("noScanCompleted").GetBoolean().Should().BeFalse();
    }

    [Fact]
    public void Run_Symbols_ResolvedFromTheExportedTable()
    {
        var (exit, output, error) = CliRunner.Run("stl", "run", Corpus("Symbols/Conveyor.awl"), "--cpu", "224", "--for", "1s",
            "--symbols", Corpus("Symbols/Conveyor-symbols.txt"), "--set", "I0.0=1@0.1s", "--set", "I0.0=0@0.2s", "--print", "Q0.0", "--print", "VW102");

        exit.Should().Be(0, error);
        output.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries).Should().Equal("Q0.0 1", "VW102 6");
    }

    [Fact]
    public void Run_ChineseExport_NamesInDiagnosticsRead()
    {
        var (exit, _, error) = CliRunner.Run("stl", "run", Corpus("Encodings/Gbk.awl"), "--cpu", "224", "--print", "Q9.9");

        exit.Should().Be(1);
        error.Should().Contain("Q9.9");
        var (ok, output, _) = CliRunner.Run("stl", "run", Corpus("Encodings/Gbk.awl"), "--cpu", "224", "--for", "1s",
            "--set", "I0.0=1@0.1s", "--set", "I0.0=0@0.2s", "--print", "VW0");
        ok.Should().Be(0);
        output.Should().Be($"VW0 1{Environment.NewLine}");
    }

    [Fact]
    public void Run_ProtectedPou_WarnsNamingIt()
    {
        var (exit, _, error) = CliRunner.Run("stl", "run", Corpus("ProtectedPou.awl"), "--cpu", "224", "--print", "Q0.1");

        exit.Should().Be(0);
        error.Should().Contain("ProtectedPou.awl:16: warning: PWM_INIT (SBR0) is password-protected: Micro/WIN exports it without its code");
    }

    [Fact]
    public void Run_MissingFile_ExitOne()
    {
        var (exit, _, error) = CliRunner.Run("stl", "run", Corpus("NoSuch.awl"), "--cpu", "224");

        exit.Should().Be(1);
        error.Should().Contain("cannot read");
    }
}
