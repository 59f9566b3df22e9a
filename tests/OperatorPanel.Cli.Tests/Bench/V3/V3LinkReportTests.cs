using OperatorPanel.Cli.Bench;
using OperatorPanel.Cli.Bench.V3;

namespace OperatorPanel.Cli.Tests.Bench.V3;

/// <summary>The v3 report on the reference line: frames from Codec, the handler run in the interpreter (simulated time, not timed).</summary>
public sealed class V3LinkReportTests
{
    [Fact]
    public void TryCreate_ReferenceLineCable_OneListBytesFromCodecTotalsAreTheirParts()
    {
        var model = new LinkTimeModel(new LineSetting(9600, "8N1", 10), 0, 5, 5, null);

        V3LinkReport.TryCreate(ReferenceLine.Create(), model, out var report, out var error).Should().BeTrue(error);

        report.Frames.List.Items.Should().HaveCount(32);
        report.Frames.List.DataBytes.Should().Be(76, "74 distinct data bytes in 30 slots, 2 SMB6 fillers");
        (report.Steady.RequestChars, report.Steady.ReplyChars).Should().Be((8, 85));
        (report.Idle.RequestChars, report.Idle.ReplyChars).Should().Be((8, 9));
        report.BinaryBoundMs.Should().BeApproximately(77.08, 0.01);
        report.Problems.Should().BeEmpty();
        // The handler's own figures beside the link's: the steady READ LIST FULL as generate --stats measures it.
        report.Stats.Steady!.Instructions.Should().BeGreaterThan(1000);
        report.Stats.Steady.ExecutionTime.TotalMilliseconds.Should().BeInRange(20, 30, "the steady refresh's PLC-time goal is 30 ms");
        report.Stats.Idle!.ExecutionTime.TotalMilliseconds.Should().BeInRange(5, 10, "the idle refresh's PLC-time goal is 10 ms");
        report.Steady.TotalMs.Should().BeApproximately(report.Steady.Parts.Sum(p => p.Ms), 1e-9);
        report.Steady.TotalMs.Should().BeGreaterThanOrEqualTo(report.Floors.Steady.TotalMs);
        report.Idle.TotalMs.Should().BeGreaterThanOrEqualTo(report.Floors.Idle.TotalMs);
        report.SummaryLine.Should().Be(string.Create(
            System.Globalization.CultureInfo.InvariantCulture,
            $"bench link: steady 93 bytes, {report.Steady.TotalMs:0.0} ms, {report.Steady.TotalMs / 77.0833:0.00} x binary bound; idle 17 bytes, {report.Idle.TotalMs:0.0} ms"));
    }

    [Theory]
    [InlineData(5)]
    [InlineData(97)]
    [InlineData(150)]
    public void TryCreate_UserProgramUpTo150Ms_EveryReplyWholeAndTakenByThePc(int scanMs)
    {
        // DEFINE LIST of 32 slots takes 84 handler scans: at 97 ms and more the probe used to give up before its reply.
        // At 5 ms every whole-list reply had a wrong check (a data byte overwritten by the next chunk's XMT count).
        var model = new LinkTimeModel(new LineSetting(9600, "8N1", 10), 0, scanMs, 5, null);

        V3LinkReport.TryCreate(ReferenceLine.Create(), model, out var report, out var error).Should().BeTrue(error);

        report.Problems.Should().BeEmpty();
        (report.Steady.RequestChars, report.Steady.ReplyChars).Should().Be((8, 85));
        report.Idle.ReplyChars.Should().Be(9);
    }

    [Fact]
    public void TryCreate_NoUserProgram_SteadyAboveTheFloorByTheHandlersFirstScans()
    {
        var model = new LinkTimeModel(new LineSetting(9600, "8N1", 10), 0, 0, 5, null);

        V3LinkReport.TryCreate(ReferenceLine.Create(), model, out var report, out _).Should().BeTrue();

        // With no user program a scan is the handler's slice alone: the steady refresh stays within ~12 ms of the wire's
        // floor (a whole list leaves after its gather: the request's check, the dispatch, 4 groups and the head first).
        report.Floors.Steady.TotalMs.Should().BeApproximately((97 * 1.0416667) + 9, 0.01);
        report.Steady.TotalMs.Should().BeInRange(report.Floors.Steady.TotalMs, report.Floors.Steady.TotalMs + 12);
    }
}
