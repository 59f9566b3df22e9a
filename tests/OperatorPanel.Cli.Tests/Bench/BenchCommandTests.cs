using System.Text.Json;

namespace OperatorPanel.Cli.Tests.Bench;

/// <summary>`opanel bench link` in-process; the measured part runs over a real socat pty (few cycles), so its numbers vary and are not asserted.</summary>
public sealed class BenchCommandTests
{
    [Fact]
    public void BenchLink_Text_PrintsEverySectionAndAVerdictPerTarget()
    {
        var (exit, output, error) = CliRunner.Run("bench", "link", "--cycles", "3");

        exit.Should().Be(0, $"stderr: {error}");
        output.Should().Contain("Reference line: CPU 226 (Current), station 2")
            .And.Contain("alarms      64  M10.0-M17.7")
            .And.Contain("Assumptions")
            .And.Contain("per exchange: PLC reply delay 5 ms + one PLC scan 10 ms = 15 ms")
            .And.Contain("Poll plan (PollPlanner, CPU known)")
            .And.Contain("this panel, READ LIST (steady state)")
            .And.Contain("this panel, plain READ")
            .And.Contain("the targets are evaluated on the steady-state refresh")
            .And.Contain("one-time cost, once per connection and after an invalidation: 1 DEFINE LIST exchange,")
            .And.Contain("one item per request, this protocol")
            .And.Contain("one item per request, seed frames")
            .And.Contain("lower bound, hex (2 chars/byte)")
            .And.Contain("lower bound, binary (1 char/byte)")
            .And.Contain("Measured round trip over a socat pty")
            .And.Contain("per full refresh:")
            .And.Contain("not line time");
        output.Should().MatchRegex(@"(PASS|FAIL) bytes on the wire")
            .And.MatchRegex(@"(PASS|FAIL) refresh time 9600 8N1")
            .And.MatchRegex(@"(PASS|FAIL) refresh time 9600 8E1");
    }

    [Fact]
    public void BenchLink_Json_GivesRowsTargetsAndTheMeasurement()
    {
        var (exit, output, error) = CliRunner.Run("bench", "link", "--cycles", "2", "--json");

        exit.Should().Be(0, $"stdout: {output} stderr: {error}");
        using var json = JsonDocument.Parse(output);
        var root = json.RootElement;
        root.GetProperty("rows").GetArrayLength().Should().Be(6);
        root.GetProperty("defineListsOnce").GetProperty("exchanges").GetInt32().Should().Be(1);
        root.GetProperty("targets").EnumerateArray().Select(t => t.GetProperty("verdict").GetString())
            .Should().HaveCount(3).And.OnlyContain(v => v == "PASS" || v == "FAIL");
        root.GetProperty("measured").GetProperty("cycles").GetInt32().Should().Be(2);
        root.GetProperty("measured").GetProperty("exchangeAverageMs").GetDouble().Should().BePositive();
    }

    [Fact]
    public void BenchLink_ZeroCycles_FailsAsBadInput()
    {
        var (exit, _, error) = CliRunner.Run("bench", "link", "--cycles", "0");

        exit.Should().Be(1);
        error.Should().Contain("--cycles 0");
    }
}
