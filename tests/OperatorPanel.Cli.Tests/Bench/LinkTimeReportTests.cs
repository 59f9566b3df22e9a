using OperatorPanel.Cli.Bench;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class LinkTimeReportTests
{
    [Fact]
    public void SummaryLine_FixedCycles_CharsTimeAndRatioToTheHexBound()
    {
        // Hex bound: 148 characters x 1.041667 ms = 154.17 ms; 400 ms / 154.17 ms = 2.59.
        var model = new LinkTimeModel(new LineSetting(9600, "8N1", 10), 5, 5, 5, null);
        var report = new LinkTimeReport("PC/PPI cable", model, Cycle(190, 400), Cycle(36, 61.25), 148);

        report.SummaryLine.Should().Be("bench link: steady 190 chars, 400.0 ms, 2.59 x hex bound; idle 36 chars, 61.3 ms");
    }

    [Fact]
    public void Create_TwoExchanges_CycleSumsTheirCharactersAndTimes()
    {
        var model = new LinkTimeModel(new LineSetting(9600, "8N1", 10), 5, 0, 5, null);
        var handler = new HandlerCost(0, TimeSpan.FromMilliseconds(5), TimeSpan.FromMilliseconds(20 * 1.0416667), "fixed");
        PlannedExchange[] exchanges = [new("a", new byte[10], 20), new("b", new byte[16], 20)];

        var cycle = CycleTime.Of("steady", model, [.. exchanges], [handler, handler]);

        // Each: characters x 1.041667 + 5 ms delay + 4 characters FIFO timeout + 5 ms gap.
        cycle.Chars.Should().Be(66);
        cycle.TotalMs.Should().BeApproximately((66 + 8) * 1.0416667 + 20, 1e-4);
    }

    private static CycleTime Cycle(int chars, double ms) =>
        new("cycle", [new ExchangeTime("x", chars / 2, chars - (chars / 2), new HandlerCost(0, TimeSpan.Zero, TimeSpan.Zero, "fixed"), [new TimePart("all", ms)])]);
}
