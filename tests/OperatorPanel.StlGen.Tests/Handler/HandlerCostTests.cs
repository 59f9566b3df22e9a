using System.Collections.Immutable;
using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen.Handler;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Golden;

namespace OperatorPanel.StlGen.Tests.Handler;

/// <summary>
/// The handler run in the interpreter at the StlTiming figures keeps what the technician notes promise
/// (SlicePart's bounds): no interrupt routine longer than 0.5 ms (the limit is 10 ms), at most 10 ms added
/// to a scan while serving, 0.2 ms without a request, and 6 to 60 scans per reply, for every worst-case request.
/// The link's reply timeout (HandlerTurnaround) must cover the scans every measured request takes.
/// </summary>
public sealed class HandlerCostTests
{
    public static TheoryData<string> Configurations => ["Cpu224_Port0_9600_2", "Cpu226_Port1_19200_17", "Cpu221Early_Port0_9600_1", "Cpu226AllWritable_115200"];

    [Theory]
    [MemberData(nameof(Configurations))]
    public void WorstCaseRequests_StayWithinTheBoundsTheNotesGive(string name)
    {
        var measured = Measure(name);

        var idle = measured.Single(m => m.Name == HandlerMeasurement.IdleName);
        var requests = measured.Where(m => m != idle).ToList();
        requests.Should().HaveCount(21).And.OnlyContain(m => m.WorstInterrupt <= Ms(SlicePart.InterruptBoundMs) && m.WorstScan <= Ms(SlicePart.ScanBoundMs));
        requests.Where(m => m.ReplyChars > 0).Should().OnlyContain(m => m.Scans >= SlicePart.FewestScans && m.Scans <= SlicePart.MostScans);
        idle.WorstScan.Should().BeLessThan(Ms(SlicePart.IdleScanBoundMs));
        requests.Single(m => m.Name.StartsWith("READ 20 items 77", StringComparison.Ordinal)).Scans.Should().BeGreaterThan(SlicePart.MostScans / 2, "the bound is near what a 20-item READ takes");
    }

    [Theory]
    [MemberData(nameof(Configurations))]
    public void PanelReplyTimeout_AllowsForEveryScanTheHandlerTakes(string name)
    {
        var measured = Measure(name);

        measured.Where(m => m.ReplyChars > 0 && !m.Name.StartsWith(ReadChanges, StringComparison.Ordinal)).Should().OnlyContain(
            m => HandlerTurnaround.ScansFor(m.RequestChars, m.ReplyChars) >= m.Scans,
            "the link's reply timeout counts HandlerTurnaround's scans, so a slow but working handler never times out");
    }

    /// <summary>
    /// READ CHANGES takes scans by the list, not by its short request and reply: the link's bound (HandlerTurnaround for
    /// a READ CHANGES request) adds the comparison's chunks to its longest reply, and must cover every measured case
    /// (20 items, 77 bytes: none, one, 40 and every byte changed).
    /// </summary>
    [Theory]
    [MemberData(nameof(Configurations))]
    public void ReadChanges_LinkBoundCoversEveryScanOfTheComparison(string name)
    {
        var measured = Measure(name);
        var bound = HandlerTurnaround.ScansFor(new ReadChangesRequest(new Station(1), 0, 1, Full: false), ProtocolLimits.RequestChars(2));

        measured.Where(IsReadChanges).Should().HaveCount(6).And.OnlyContain(m => m.Scans <= bound);
    }

    /// <summary>
    /// READ CHANGES OF LISTS: the link's bound (its frames at the longest 09 reply, and one comparison per list of the
    /// mask) covers the measured 2-list and 4-list requests; two idle lists take fewer scans in one 09 than in two 08s.
    /// </summary>
    [Theory]
    [MemberData(nameof(Configurations))]
    public void ReadChangesOfLists_LinkBoundCoversEveryScanAndTwoIdleListsCostLessThanTwoReadChanges(string name)
    {
        var measured = Measure(name);
        var lists = measured.Where(m => m.Name.StartsWith(ReadChangesOfLists, StringComparison.Ordinal)).ToList();
        var idle = lists.Single(m => m.Name.Contains("2 lists idle", StringComparison.Ordinal));
        var twoReadChanges = measured.Where(m => m.Name.Contains(" of 2, none changed", StringComparison.Ordinal)).ToList();

        lists.Should().HaveCount(3).And.OnlyContain(m => m.Scans <= Bound((byte)(m.Name.Contains("4 lists", StringComparison.Ordinal) ? 0b1111 : 0b0011)));
        twoReadChanges.Should().HaveCount(2);
        idle.Scans.Should().BeLessThan(twoReadChanges.Sum(m => m.Scans));
        (idle.RequestChars + idle.ReplyChars).Should().Be(36);
    }

    private static int Bound(byte mask) =>
        HandlerTurnaround.ScansFor(new ReadChangesOfListsRequest(new Station(1), mask), ProtocolLimits.RequestChars(1));

    private const string ReadChanges = "READ CHANGES", ReadChangesOfLists = "READ CHANGES OF LISTS";

    private static bool IsReadChanges(MeasuredRequest m) =>
        m.Name.StartsWith(ReadChanges, StringComparison.Ordinal) && !m.Name.StartsWith(ReadChangesOfLists, StringComparison.Ordinal);

    private static ImmutableArray<MeasuredRequest> Measure(string name)
    {
        var options = name == "Cpu226AllWritable_115200"
            ? new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu226), Port = 1, BaudRate = 115200, Station = 5, WriteMask = 0x3C }
            : HandlerGoldenTests.OptionsFor(name);
        var generated = HandlerGenerator.Generate(options);
        var stats = generated.Stats!;
        var dataStart = stats.FirstVByte >= HandlerMeasurement.DataBytes ? 0 : stats.LastVByte + 1;

        HandlerMeasurement.TryMeasure(
            generated.AwlText, options.Cpu, options.Port, new Station(options.Station),
            new LineSettings(options.BaudRate, options.Parity, options.DataBits), dataStart, out var measured, out var error).Should().BeTrue(error);
        return measured;
    }

    private static TimeSpan Ms(string text) => TimeSpan.FromMilliseconds(double.Parse(text, CultureInfo.InvariantCulture));
}
