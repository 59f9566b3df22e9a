using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class HandlerCostsTests
{
    [Fact]
    public void Bound_SixteenAndTwentyCharacters_CoreScansTimesTheLargestSlice()
    {
        // HandlerTurnaround: 5 + ceil(16 / 6) + ceil(20 / 6) = 12 scans, each with a 10 ms slice.
        var cost = HandlerCosts.Bound(new PlannedExchange("x", new byte[16], 20));

        cost.Scans.Should().Be(12);
        cost.HandlerAlone.Should().Be(TimeSpan.FromMilliseconds(120));
        cost.Source.Should().StartWith("bound");
    }

    [Fact]
    public void LinkBound_ReadChangesOfTwoLists_TheLinksTimeoutBoundWithOneComparisonPerList()
    {
        var exchange = new PlannedExchange("09", RequestCodec.Encode(new ReadChangesOfListsRequest(new Station(2), 0x03)), 22);

        // 5 + ceil(14 / 6) + ceil(254 / 6) for the longest reply (118 payload bytes), + 2 x 35 comparison scans.
        HandlerCosts.LinkBound(exchange).Should().Be(5 + 3 + 43 + (2 * HandlerTurnaround.ChangeComparisonScans));
    }

    [Fact]
    public void LinkBound_BytesThatAreNoRequest_TheBoundOfTheirCharacters()
    {
        HandlerCosts.LinkBound(new PlannedExchange("x", new byte[16], 20)).Should().Be(12);
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

        // Neither a reply length other than Core's nor more scans than the link's reply timeout allows.
        costs.Problems.Should().BeEmpty();
        costs.Steady.Concat(costs.Idle).Should().OnlyContain(c => c.Source.StartsWith("measured", StringComparison.Ordinal) && c.Scans > 0);
    }

    [Fact]
    public void Measure_OneListLine_TheHandlerServesReadChangesWithTheRepliesCoreSizes()
    {
        var line = new BenchLine(
            new Station(1),
            CpuProfiles.For(CpuModel.Cpu224),
            [new("inputs", PlcAddress.Parse("IB0")), new("memory", PlcAddress.Parse("VW100")), new("alarms", PlcAddress.Parse("M2.3"))]);
        var cycles = RefreshCycles.For(line.Plan());
        HandlerProbe.TryCreate(line.Cpu, line.Station, new LineSetting(9600, "8N1", 10).Settings, 5, out var probe, out var error).Should().BeTrue(error);

        var costs = HandlerCosts.Measure(cycles, probe, error);

        cycles.Idle.Select(e => e.Name).Should().Equal("READ CHANGES OF LISTS 1");
        costs.Problems.Should().BeEmpty("the handler answers every exchange with the reply length Core computes, within the link's bound");
        costs.Idle.Single().Source.Should().StartWith("measured");
    }
}
