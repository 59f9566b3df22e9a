using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Bench;

/// <summary><c>opanel bench stl</c>: the generated handler served in the interpreter as fast as it runs (figures are printed, not judged).</summary>
public sealed class StlBenchCommandTests
{
    [Fact]
    public void BenchStl_Json_EveryWorkloadAnsweredWithFigures()
    {
        var run = CliRunner.Run("bench", "stl", "--requests", "2", "--json");

        run.ExitCode.Should().Be(0, run.Error);
        using var json = JsonDocument.Parse(run.Out);
        var rows = json.RootElement.EnumerateArray().ToList();
        // v2 frames: IDENTIFY 12; WRITE payload AREA OFFSET(2) LENGTH + 117 bytes -> 12 + 2 x 121 = 254; one-item READ 22.
        rows.Select(r => r.GetProperty("requestChars").GetInt32()).Should().Equal(12, 254, 22);
        rows.Should().OnlyContain(r => r.GetProperty("answered").GetInt32() == 2 && r.GetProperty("replyChars").GetInt32() > 0
            && r.GetProperty("requestsPerRealSecond").GetDouble() > 0 && r.GetProperty("instructionsPerRequest").GetDouble() > 0);
    }

    [Theory]
    [InlineData("--requests", "0")]
    [InlineData("--baud", "12345")]
    public void BenchStl_BadOption_ExitsOne(string option, string value)
    {
        CliRunner.Run("bench", "stl", option, value).ExitCode.Should().Be(1);
    }
}
