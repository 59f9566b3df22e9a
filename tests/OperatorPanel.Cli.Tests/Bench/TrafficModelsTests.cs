using System.Collections.Immutable;
using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Tests.Bench;

/// <summary>A tiny line counted by hand: IB0, VW100 and M2.3 on a CPU 224 at station 1.</summary>
public sealed class TrafficModelsTests
{
    private static readonly BenchLine Tiny = new(
        new Station(1),
        CpuProfiles.For(CpuModel.Cpu224),
        [new("inputs", PlcAddress.Parse("IB0")), new("memory", PlcAddress.Parse("VW100")), new("alarms", PlcAddress.Parse("M2.3"))]);

    private static readonly string[] Overlapping = ["M2.0", "M2.7", "MB2", "VW100", "VD100"];

    [Fact]
    public void FromPlan_TinyLine_OneReadListOfTwelveCharacters()
    {
        var plan = Tiny.Plan();
        var figures = TrafficModels.FromPlan(plan);

        // Request: '<' STATION SEQ CMD LIST BCC '>' = 1 + 8 + 2 + 1 = 12; the reply is that of the READ (20).
        figures.Should().Be(new TrafficFigures(TrafficModels.Planned, 1, 12, 20));
        RequestCodec.Encode(new ReadListRequest(Tiny.Station, 1, 1)).Should().HaveCount(12);
        ResponseCodec.Encode(new ReadListResponse(Tiny.Station, 1, [1, 2, 3, 4])).Should().HaveCount(20);
    }

    [Fact]
    public void DefineListsOnce_TinyLine_OneDefineOfThreeItems()
    {
        var plan = Tiny.Plan();
        var figures = TrafficModels.DefineListsOnce(plan);

        // Request: '<' STATION SEQ CMD LIST COUNT + 3 × 8 + BCC '>' = 1 + 10 + 24 + 2 + 1 = 38; reply 12 (STATUS 00 only).
        figures.Should().Be(new TrafficFigures(TrafficModels.DefineLists, 1, 38, 12));
        RequestCodec.Encode(new DefineListRequest(Tiny.Station, 1, 1, plan.Frames[0].Items)).Should().HaveCount(38);
        ResponseCodec.Encode(new DefineListResponse(Tiny.Station, 1)).Should().HaveCount(12);
    }

    [Fact]
    public void PlainReads_TinyLine_OneFrameOfThreeItems()
    {
        var plan = Tiny.Plan();
        var figures = TrafficModels.PlainReads(plan);

        // Request: '<' STATION SEQ CMD COUNT + 3 × (AREA OFFSET LENGTH) + BCC '>' = 1 + 8 + 24 + 2 + 1 = 36.
        // Reply: '<' STATION SEQ CMD STATUS + 4 data bytes + BCC '>' = 1 + 8 + 8 + 2 + 1 = 20.
        figures.Should().Be(new TrafficFigures(TrafficModels.PlainRead, 1, 36, 20));
        RequestCodec.Encode(new ReadRequest(Tiny.Station, 1, plan.Frames[0].Items)).Should().HaveCount(36);
        ResponseCodec.Encode(new ReadResponse(Tiny.Station, 1, [1, 2, 3, 4])).Should().HaveCount(20);
    }

    [Fact]
    public void OneItemPerRequest_TinyLine_ThreeReadsOfOneItem()
    {
        var figures = TrafficModels.OneItemPerRequest(Tiny, PollCostModel.Default);

        // 3 requests of 12 + 8 characters; replies 12 + 2 (IB0), 12 + 4 (VW100), 12 + 2 (MB2 for M2.3).
        figures.Should().Be(new TrafficFigures(TrafficModels.PerItem, 3, 60, 44));
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
    [InlineData(9600, "8N1", 10, 58.333)]   // 56 characters x 1.0417 ms
    [InlineData(9600, "8E1", 11, 64.167)]   // 56 x 1.1458 ms
    [InlineData(38400, "8N1", 10, 14.583)]  // 56 x 0.2604 ms
    public void LineMs_TinyPlan_CharactersTimesCharacterTimeOnly(int baud, string format, int bits, double expected)
    {
        var figures = TrafficModels.PlainReads(Tiny.Plan());

        figures.LineMs(new LineSetting(baud, format, bits)).Should().BeApproximately(expected, 0.001);
    }

    [Fact]
    public void FromPlan_ReferenceLine_MatchesTheEncodedReadListAndReadFrames()
    {
        var line = ReferenceLine.Create();
        var plan = line.Plan();
        var figures = TrafficModels.FromPlan(plan);
        var lists = ReadListAssignment.For(plan);

        var requests = Enumerable.Range(0, plan.FrameCount).Sum(i => RequestCodec.Encode(lists.TryGetValue(i, out var list)
            ? new ReadListRequest(line.Station, 0, list)
            : new ReadRequest(line.Station, 0, plan.Frames[i].Items)).Length);
        var replies = plan.Frames.Sum(f => ResponseCodec.Encode(new ReadResponse(line.Station, 0, ImmutableArray.Create(new byte[f.DataBytes]))).Length);
        figures.RequestChars.Should().Be(requests);
        figures.ReplyChars.Should().Be(replies);
    }
}
