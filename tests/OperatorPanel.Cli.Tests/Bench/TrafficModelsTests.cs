using System.Collections.Immutable;
using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Tests.Bench;

/// <summary>
/// A tiny line counted by hand: IB0, VW100 and M2.3 on a CPU 224 at station 1. Protocol v2 sizes: a request with P
/// payload bytes is '&lt;' + 2 x (3 + P) + 4 check + '&gt;' = 12 + 2P; a reply 6 + 2 x (6 + P) = 18 + 2P.
/// </summary>
public sealed class TrafficModelsTests
{
    private static readonly BenchLine Tiny = new(
        new Station(1),
        CpuProfiles.For(CpuModel.Cpu224),
        [new("inputs", PlcAddress.Parse("IB0")), new("memory", PlcAddress.Parse("VW100")), new("alarms", PlcAddress.Parse("M2.3"))]);

    private static readonly string[] Overlapping = ["M2.0", "M2.7", "MB2", "VW100", "VD100"];

    [Fact]
    public void RefreshCycles_TinyLine_ListSetUpThenFullAndIdleReadChanges()
    {
        var plan = Tiny.Plan();
        var cycles = RefreshCycles.For(plan);

        // One list of 3 items and 4 bytes. DEFINE LIST: payload LIST COUNT + 3 x 4 = 14 -> 40, reply 18.
        // READ CHANGES: payload LIST FLAGS -> 16; FULL reply K + 4 bytes -> 28.
        // Idle, READ CHANGES OF LISTS: payload MASK -> 14; reply K = 0 -> 20.
        ReadListAssignment.For(plan).Should().HaveCount(1);
        cycles.Setup.Select(e => (e.Name, e.RequestChars, e.ReplyChars)).Should().Equal(("DEFINE LIST 1", 40, 18), ("READ CHANGES 1 FULL", 16, 28));
        cycles.Steady.Select(e => (e.Name, e.RequestChars, e.ReplyChars)).Should().Equal(("READ CHANGES 1 FULL", 16, 28));
        cycles.Idle.Select(e => (e.Name, e.RequestChars, e.ReplyChars)).Should().Equal(("READ CHANGES OF LISTS 1", 14, 20));
    }

    [Fact]
    public void RefreshCycles_TinyLine_ReplySizesAreThoseCoreEncodes()
    {
        var cycles = RefreshCycles.For(Tiny.Plan());
        var full = new ReadChangesRequest(Tiny.Station, 1, 1, true);
        var idle = new ReadChangesOfListsRequest(Tiny.Station, 1, 0x01);

        cycles.Steady[0].ReplyChars.Should().Be(ResponseCodec.Encode(ReadChangesResponse.Whole(Tiny.Station, 1, [1, 2, 3, 4]), full).Length);
        Decoded(cycles.Idle[0].Request).Should().BeOfType<ReadChangesOfListsRequest>().Which.ListMask.Should().Be(0x01);
        cycles.Idle[0].ReplyChars.Should().Be(ResponseCodec.Encode(new ReadChangesOfListsResponse(Tiny.Station, 1, [ListChanges.Pairs(1, [])]), idle).Length);
        cycles.Setup[0].ReplyChars.Should().Be(ResponseCodec.Encode(new DefineListResponse(Tiny.Station, 1), new DefineListRequest(Tiny.Station, 1, 1, Tiny.Plan().Frames[0].Items)).Length);
    }

    [Fact]
    public void FromCycle_IdleOneList_ThirtyFourCharacters()
    {
        var figures = TrafficModels.FromCycle(TrafficModels.Idle, RefreshCycles.For(Tiny.Plan()).Idle);

        figures.Should().Be(new TrafficFigures(TrafficModels.Idle, 1, 14, 20));
    }

    [Fact]
    public void RefreshCycles_ReferenceLine_IdleIsOneReadChangesOfListsOverBothListsInThirtySixCharacters()
    {
        var line = ReferenceLine.Create();
        var cycles = RefreshCycles.For(line.Plan());

        // Request payload MASK 03 -> 14 characters; reply K = 0 for list 1 and for list 2 -> 18 + 2 x 2 = 22.
        cycles.Idle.Select(e => (e.Name, e.RequestChars, e.ReplyChars)).Should().Equal(("READ CHANGES OF LISTS 1+2", 14, 22));
        Decoded(cycles.Idle[0].Request).Should().BeOfType<ReadChangesOfListsRequest>().Which.Lists.Should().Equal(1, 2);
        TrafficModels.FromCycle(TrafficModels.Idle, cycles.Idle).TotalChars.Should().Be(36);
    }

    [Fact]
    public void PlainReads_TinyLine_OneFrameOfThreeItems()
    {
        var plan = Tiny.Plan();
        var figures = TrafficModels.PlainReads(plan);

        // Request payload COUNT + 3 x (AREA OFFSET LENGTH) = 13 -> 38; reply 4 data bytes -> 26.
        figures.Should().Be(new TrafficFigures(TrafficModels.PlainRead, 1, 38, 26));
        RequestCodec.Encode(new ReadRequest(Tiny.Station, 1, plan.Frames[0].Items)).Should().HaveCount(38);
    }

    [Fact]
    public void OneItemPerRequest_TinyLine_ThreeReadsOfOneItem()
    {
        var figures = TrafficModels.OneItemPerRequest(Tiny);

        // 3 requests of 12 + 2 x 5 = 22; replies 18 + 2 (IB0), 18 + 4 (VW100), 18 + 2 (MB2 for M2.3).
        figures.Should().Be(new TrafficFigures(TrafficModels.PerItem, 3, 66, 62));
    }

    [Fact]
    public void SeedOneItemPerRequest_TinyLine_SumsTheSeedFrames()
    {
        var figures = TrafficModels.SeedOneItemPerRequest(Tiny);

        // <IB0?> 6 + <VWxx?> 7 + <Mxx.y?> 8; <IB0=z> 7 + <VWxx=zz> 9 + <Mxx.y=z> 9.
        figures.Should().Be(new TrafficFigures(TrafficModels.SeedPerItem, 3, 21, 25));
    }

    [Fact]
    public void LowerBounds_TinyLine_CountEachDataByteOnce()
    {
        // IB0, VB100, VB101, MB2: 4 bytes; 8 hex characters or 4 binary ones; no frames.
        Tiny.DistinctDataBytes.Should().Be(4);
        TrafficModels.LowerBoundAsHex(Tiny).Should().Be(new TrafficFigures(TrafficModels.LowerBoundHex, 0, 0, 8));
        TrafficModels.LowerBoundAsBinary(Tiny).Should().Be(new TrafficFigures(TrafficModels.LowerBoundBinary, 0, 0, 4));
    }

    [Fact]
    public void DistinctDataBytes_BitsOfOneByteAndOverlappingWords_CountTheByteOnce()
    {
        var line = Tiny with
        {
            Tags = [.. Overlapping.Select(a => new BenchTag("x", PlcAddress.Parse(a)))],
        };

        line.DistinctDataBytes.Should().Be(5, "MB2 once, VB100-VB103 once");
    }

    [Theory]
    [InlineData(9600, "8N1", 10, 66.667)]   // 64 characters x 1.0417 ms
    [InlineData(9600, "8E1", 11, 73.333)]   // 64 x 1.1458 ms
    [InlineData(38400, "8N1", 10, 16.667)]  // 64 x 0.2604 ms
    public void LineMs_TinyPlan_CharactersTimesCharacterTimeOnly(int baud, string format, int bits, double expected)
    {
        var figures = TrafficModels.PlainReads(Tiny.Plan());

        figures.LineMs(new LineSetting(baud, format, bits)).Should().BeApproximately(expected, 0.001);
    }

    [Fact]
    public void PlainReads_ReferenceLine_MatchesTheEncodedReadFrames()
    {
        var line = ReferenceLine.Create();
        var plan = line.Plan();
        var figures = TrafficModels.PlainReads(plan);

        var requests = plan.Frames.Sum(f => RequestCodec.Encode(new ReadRequest(line.Station, 0, f.Items)).Length);
        var replies = plan.Frames.Sum(f => ResponseCodec.Encode(new ReadResponse(line.Station, 0, ImmutableArray.Create(new byte[f.DataBytes]))).Length);
        figures.RequestChars.Should().Be(requests);
        figures.ReplyChars.Should().Be(replies);
    }

    private static PlcRequest Decoded(byte[] frame)
    {
        FrameCodec.TryDecode(frame, out var decoded, out var error).Should().BeTrue(error.ToString());
        RequestCodec.TryParse(decoded, null, out var request, out var refusal).Should().BeTrue(refusal.ToString());
        return request;
    }
}
