using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Tests.Bench;

public sealed class HandlerCostsTests
{
    private static readonly LinkTimeModel Cable9600 = new(new LineSetting(9600, "8N1", 10), ReplyDelayMs: 5, ProgramScanMs: 5, LinkGapMs: 5, Radio: null);

    [Fact]
    public void Bound_SixteenAndTwentyCharacters_CoreScansOfTheLargestSliceAndTheUserProgramThenTheDelay()
    {
        // HandlerTurnaround: 5 + ceil(16 / 6) + ceil(20 / 6) = 12 scans, each a 10 ms slice and 5 ms of user program.
        var cost = HandlerCosts.Bound(new PlannedExchange("x", new byte[16], 20), Cable9600);

        cost.Scans.Should().Be(12);
        cost.UntilFirstReply.Should().Be(TimeSpan.FromMilliseconds((12 * 15) + 5));
        cost.ReplyOnBus.TotalMilliseconds.Should().BeApproximately(20 * 1.0416667, 1e-4);
        cost.Source.Should().StartWith("bound");
    }

    [Fact]
    public void Probe_ReferenceLineFullList_TheReplyStartsBeforeTheHandlerIsDoneAndTakesNoLessThanItsCharacters()
    {
        var line = ReferenceLine.Create();
        var cycles = RefreshCycles.For(line.Plan());
        HandlerProbe.TryCreate(line.Cpu, line.Station, Cable9600.Line.Settings, 5, TimeSpan.FromMilliseconds(5), out var probe, out var error).Should().BeTrue(error);

        var costs = HandlerCosts.Measure(cycles, Cable9600, probe, error);

        // READ CHANGES 1 FULL: 150 reply characters. Each of the handler's scans runs 5 ms of user program, so a first
        // character sooner than scans x 5 ms after the request left while the handler still worked on the reply.
        var full = costs.Steady[0];
        full.UntilFirstReply.Should().BeLessThan(TimeSpan.FromMilliseconds(full.Scans * 5));
        full.ReplyOnBus.Should().BeGreaterThanOrEqualTo(TimeSpan.FromMilliseconds(150 * 1.0416));
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

        var costs = HandlerCosts.Measure(cycles, Cable9600, probe: null, probeError: "no handler");

        costs.Steady.Should().HaveCount(cycles.Steady.Length).And.OnlyContain(c => c.Source.StartsWith("bound", StringComparison.Ordinal));
        costs.Problems.Should().Equal("handler not run: no handler");
    }

    [Fact]
    public void Measure_ReferenceLine_TheGeneratedHandlerAnswersEveryExchange()
    {
        var line = ReferenceLine.Create();
        var cycles = RefreshCycles.For(line.Plan());
        HandlerProbe.TryCreate(line.Cpu, line.Station, Cable9600.Line.Settings, 5, TimeSpan.FromMilliseconds(5), out var probe, out var error).Should().BeTrue(error);

        var costs = HandlerCosts.Measure(cycles, Cable9600, probe, error);

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
        HandlerProbe.TryCreate(line.Cpu, line.Station, Cable9600.Line.Settings, 5, TimeSpan.FromMilliseconds(5), out var probe, out var error).Should().BeTrue(error);

        var costs = HandlerCosts.Measure(cycles, Cable9600, probe, error);

        cycles.Idle.Select(e => e.Name).Should().Equal("READ CHANGES OF LISTS 1");
        costs.Problems.Should().BeEmpty("the handler answers every exchange with the reply length Core computes, within the link's bound");
        costs.Idle.Single().Source.Should().StartWith("measured");
    }
}
