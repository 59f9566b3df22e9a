using OperatorPanel.Cli.Bench;

namespace OperatorPanel.Cli.Tests.Bench;

/// <summary>`opanel bench link --ppi`: the simulated PPI refresh against the handshake's arithmetic.</summary>
public sealed class PpiBenchTests
{
    [Fact]
    public async Task Run_9600WithoutUserProgram_IsTheHandshakesArithmetic()
    {
        var report = await PpiBench.RunAsync(ReferenceLine.Create(), 9600, scanMs: 0, refreshes: 3, usbLatencyMs: 16);

        var job = report.Plan.Requests.Should().ContainSingle().Subject;
        var (request, answer) = (job.RequestPduLength + 9, job.AnswerPduLength + 9);
        report.SteadyChars.Should().Be(request + 1 + 6 + answer, "request, E5, one poll, the answer: a scan of 0.25 ms is over before the poll");
        var c = 11 * 1000.0 / 9600;
        // Request; the CPU's E5 after the cable's 4 ms turnaround; the 16550 hands it over 4 characters late (longer than
        // the 33-bit pause); the poll; 4 ms again; the answer, handed over 4 characters late.
        var expected = (request * c) + 4 + c + (4 * c) + (6 * c) + 4 + (answer * c) + (4 * c);
        report.SteadyMs.Should().BeApproximately(expected, 0.01);
        report.Refreshes.Should().OnlyContain(r => r.EmptyPolls == 0);
    }

    [Fact]
    public async Task Run_LongScan_PollsUntilTheCommunicationPhase()
    {
        var report = await PpiBench.RunAsync(ReferenceLine.Create(), 19200, scanMs: 100, refreshes: 8, usbLatencyMs: 16);

        report.Refreshes.Average(r => r.EmptyPolls).Should().BeGreaterThan(1);
        report.Refreshes.Max(r => r.Ms).Should().BeGreaterThan(report.Refreshes.Min(r => r.Ms), "a refresh starts wherever the scan is");
    }

    [Fact]
    public void BenchLinkPpi_Text_EndsWithTheFreeportBenchsSummaryFormat()
    {
        var (exit, output, error) = CliRunner.Run("bench", "link", "--ppi", "--baud", "19200");

        exit.Should().Be(0, $"stderr: {error}");
        output.Should().Contain("over PPI at 19200 baud 8E1 (MODELLED by simulation)").And.Contain("PC/PPI cable on a COM port");
        var lines = output.TrimEnd().Split('\n');
        lines[^1].Should().MatchRegex(@"^bench link: steady \d+ chars, \d+\.\d ms, \d+\.\d\d x hex bound; idle \d+ chars, \d+\.\d ms$");
    }

    [Theory]
    [InlineData("--baud", "38400")]
    [InlineData("--radio", null)]
    [InlineData("--usb-latency-ms", "0")]
    public void BenchLinkPpi_BadOption_FailsAsBadInput(string option, string? value)
    {
        string[] args = value is null ? ["bench", "link", "--ppi", option] : ["bench", "link", "--ppi", option, value];

        var (exit, _, error) = CliRunner.Run(args);

        exit.Should().Be(1);
        error.Should().Contain(option);
    }
}
