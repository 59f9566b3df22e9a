using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class HandlerCostsTests
{
    [Fact]
    public void Bound_SixteenAndTwentyCharacters_CoreScansTimesTheLargestSlice()
    {
        // HandlerTurnaround: 4 + ceil(16 / 12) + ceil(20 / 12) = 8 scans, each with a 10 ms slice.
        var cost = HandlerCosts.Bound(new PlannedExchange("x", new byte[16], 20));

        cost.Scans.Should().Be(8);
        cost.HandlerAlone.Should().Be(TimeSpan.FromMilliseconds(80));
        cost.Source.Should().StartWith("bound");
    }

    [Fact]
    public void Measure_NoProbe_EveryExchangeBoundAndTheReasonNamed()
    {
        var cycles = RefreshCycles.For(ReferenceLine.Create().Plan());

        var costs = HandlerCosts.Measure(cycles, probe: null, probeError: "no handler");

        costs.Steady.Should().HaveCount(cycles.Steady.Length).And.OnlyContain(c => c.Source.StartsWith("bound", StringComparison.Ordinal));
        costs.Problems.Should().Equal("handler not run: no handler");
    }

    [Fact]
    public void Measure_ReferenceLine_TheGeneratedHandlerAnswersEveryExchange()
    {
        var line = ReferenceLine.Create();
        var cycles = RefreshCycles.For(line.Plan());
        HandlerProbe.TryCreate(line.Cpu, line.Station, new LineSetting(9600, "8N1", 10).Settings, 5, out var probe, out var error).Should().BeTrue(error);

        var costs = HandlerCosts.Measure(cycles, probe, error);

        costs.Problems.Should().BeEmpty();
        costs.Steady.Concat(costs.Idle).Should().OnlyContain(c => c.Source.StartsWith("measured", StringComparison.Ordinal) && c.Scans > 0);
    }
}
