using System.Collections.Immutable;
using OperatorPanel.Cli.Bench;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class BenchTargetsTests
{
    private static readonly ExchangeTiming NoDeadTime = new(0, 0);
    private static readonly TrafficFigures Planned = new(TrafficModels.Planned, 1, 40, 60);
    private static readonly TrafficFigures Seed = new(TrafficModels.SeedPerItem, 10, 200, 200);
    private static readonly TrafficFigures Binary = new(TrafficModels.LowerBoundBinary, 0, 0, 20);

    [Theory]
    [InlineData(800, true)]  // exactly 8 times fewer
    [InlineData(799, false)]
    public void Evaluate_BytesRatio_PassesFromEightTimesFewer(int perItemChars, bool pass)
    {
        var targets = Evaluate(perItemChars, lowerHexChars: 40);

        var bytes = targets.Single(t => t.Name == "bytes on the wire");
        bytes.Pass.Should().Be(pass);
        bytes.Ratio.Should().BeApproximately(perItemChars / 100.0, 1e-9);
        bytes.Detail.Should().Contain($"{perItemChars} / 100").And.Contain("400 / 100 = 4.00x");
    }

    [Theory]
    [InlineData(40, true)]  // 100 / 40 = 2.5: on the limit
    [InlineData(39, false)] // 100 / 39 = 2.56
    public void Evaluate_TimeRatio_PassesUpToTwoAndAHalfTheHexBoundAtBothFormats(int lowerHexChars, bool pass)
    {
        var targets = Evaluate(1000, lowerHexChars);

        var times = targets.Where(t => t.Name.StartsWith("refresh time", StringComparison.Ordinal)).ToList();
        times.Select(t => t.Name).Should().Equal("refresh time 9600 8N1", "refresh time 9600 8E1");
        times.Should().OnlyContain(t => t.Pass == pass && Math.Abs(t.Ratio - (100.0 / lowerHexChars)) < 1e-9);
        times[0].Detail.Should().Contain("5.00x the binary lower bound");
    }

    [Fact]
    public void Evaluate_DeadTimePerExchange_CountsAgainstThePlanOnly()
    {
        // 100 characters at 9600 8N1 = 104.17 ms + 1 exchange × 15 ms = 119.17 ms; the bound has no exchange: 41.67 ms.
        var targets = BenchTargets.Evaluate(Planned, new(TrafficModels.PerItem, 10, 500, 500), Seed, new(TrafficModels.LowerBoundHex, 0, 0, 40), Binary, ExchangeTiming.Default);

        targets.Single(t => t.Name == "refresh time 9600 8N1").Ratio.Should().BeApproximately(119.1667 / 41.6667, 1e-3);
    }

    private static ImmutableArray<TargetResult> Evaluate(int perItemChars, int lowerHexChars) =>
        BenchTargets.Evaluate(
            Planned,
            new TrafficFigures(TrafficModels.PerItem, 10, perItemChars / 2, perItemChars - (perItemChars / 2)),
            Seed,
            new TrafficFigures(TrafficModels.LowerBoundHex, 0, 0, lowerHexChars),
            Binary,
            NoDeadTime);
}
