using System.Buffers.Binary;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// The handler merged into the exported Filler program (Merge/UserPrograms/Filler.awl) by HandlerMerger still answers
/// like the reference model, while the user's code runs beside it: its conveyor rung holds Q0.0, its valve rung
/// Q0.1, and its 100 ms timed interrupt counts the filling time in VW16. Requests keep off the user's bytes.
/// </summary>
public sealed class MergedDifferentialTests
{
    private const int BaseSeed = 4_1000;

    private static readonly string Filler = UserProgram.Read("Filler.awl");

    public static TheoryData<int> Configurations => [.. Enumerable.Range(0, All.Length)];

    /// <summary>The CPUs with the analog input the Filler's SCALE reads (AIW0), the default and a moved footprint.</summary>
    private static HandlerOptions[] All =>
    [
        UserProgram.Cpu224,
        new()
        {
            Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu226), Port = 1, BaudRate = 19200, Parity = Parity.Even, Station = 17,
            BufferStart = 1001, CharTimeoutMs = 100, FirstSubroutine = 20, FirstInterrupt = 1, ReplyDelayMs = 1,
        },
        new() { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224XP), Station = 126, BaudRate = 115200, WriteMask = 0x10, ReplyDelayMs = 255 },
    ];

    [Theory]
    [MemberData(nameof(Configurations))]
    public void MergedFiller_RandomExchanges_AnswerLikeTheReferenceWhileTheUserCodeRuns(int index)
    {
        var options = All[index];
        var seed = BaseSeed + index;
        var random = new Random(seed);
        var harness = new DifferentialHarness(options, random, Filler);
        // Conveyor on (I0.0 start, I0.1 stop released), no offset, set level above any scaled value: the valve opens.
        harness.Poke(ProtocolArea.I, 0, 0x01);
        harness.Poke(ProtocolArea.V, 10, 0, 0, 0, 0, 0x7F, 0xFF, 0, 0);
        var start = harness.Now;
        var requests = new RandomRequests(random, harness, options.Station, options.CharTimeoutMs);

        var replies = DifferentialRun.Run(harness, requests, HandlerDifferentialTests.ExchangesPerConfiguration, $"seed {seed}, merged Filler, {DifferentialConfigurations.Describe(options)}");

        replies.Should().BeGreaterThan(HandlerDifferentialTests.ExchangesPerConfiguration / 4, "most exchanges are answered");
        harness.User.Touches(ProtocolArea.V, 0, 57).Should().BeTrue("the Filler uses VW0-VW16, VD20, VB40-VB57");
        (harness.Interpreted(ProtocolArea.Q)[0] & 0x03).Should().Be(0x03, "the user's rungs hold the conveyor and the valve");
        var ticks = (int)((harness.Now - start).Ticks / TimeSpan.FromMilliseconds(100).Ticks);
        int filling = BinaryPrimitives.ReadUInt16BigEndian(harness.Interpreted(ProtocolArea.V).AsSpan(16));
        filling.Should().BeCloseTo(ticks, 2, "the user's timed interrupt counted every 100 ms beside the handler");
    }
}
