using System.Collections.Immutable;
using OperatorPanel.Cli.Bench;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class BenchTargetsTests
{
    private static readonly LineSetting Line = new(9600, "8N1", 10);
    private static readonly TrafficFigures Planned = new(TrafficModels.Planned, 1, 40, 60);
    private static readonly TrafficFigures Seed = new(TrafficModels.SeedPerItem, 10, 200, 200);

    [Theory]
    [InlineData(800, true)]  // exactly 8 times fewer
    [InlineData(799, false)]
    public void Evaluate_BytesRatio_PassesFromEightTimesFewer(int perItemChars, bool pass)
    {
        var targets = Evaluate(perItemChars, steadyMs: 100, hexChars: 100, idleChars: 36);

        var bytes = targets.Single(t => t.Name == "bytes on the wire");
        bytes.Pass.Should().Be(pass);
        bytes.Ratio.Should().BeApproximately(perItemChars / 100.0, 1e-9);
        bytes.Detail.Should().Contain($"{perItemChars} / 100").And.Contain("400 / 100 = 4.00x");
    }

    [Theory]
    [InlineData(160, true)]  // 160 ms against 100 characters x 1.0417 ms = 104.17 ms: 1.536x
    [InlineData(170, false)] // 1.632x
    public void Evaluate_SteadyTime_PassesUpToOnePointSixTheHexBound(double steadyMs, bool pass)
    {
        var targets = Evaluate(1000, steadyMs, hexChars: 100, idleChars: 36);

        var steady = targets.Single(t => t.Name.StartsWith("steady refresh", StringComparison.Ordinal));
        steady.Name.Should().Be("steady refresh 9600 8N1 (PC/PPI cable, modelled)");
        steady.Pass.Should().Be(pass);
        steady.Ratio.Should().BeApproximately(steadyMs / 104.16667, 1e-4);
    }

    [Theory]
    [InlineData(40, true)]
    [InlineData(41, false)]
    public void Evaluate_IdleStation_PassesUpToFortyCharacters(int idleChars, bool pass)
    {
        var targets = Evaluate(1000, steadyMs: 100, hexChars: 100, idleChars);

        targets.Single(t => t.Name == "idle station").Pass.Should().Be(pass);
    }

    private static ImmutableArray<TargetResult> Evaluate(int perItemChars, double steadyMs, int hexChars, int idleChars)
    {
        var model = new LinkTimeModel(Line, 5, 5, 5, null);
        var time = new LinkTimeReport("PC/PPI cable", model, Cycle(100, steadyMs), Cycle(idleChars, 40), hexChars);
        return BenchTargets.Evaluate(Planned, new TrafficFigures(TrafficModels.PerItem, 10, perItemChars / 2, perItemChars - (perItemChars / 2)), Seed, time);
    }

    private static CycleTime Cycle(int chars, double ms) =>
        new("cycle", [new ExchangeTime("x", chars / 2, chars - (chars / 2), new HandlerCost(0, TimeSpan.Zero, TimeSpan.Zero, "fixed"), [new TimePart("all", ms)])]);
}
