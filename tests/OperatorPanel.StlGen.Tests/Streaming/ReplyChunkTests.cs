using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Streaming;

/// <summary>
/// The reply leaves in chunks while the handler computes its check (docs/protocol-v2.md section 6, steps 6 and 7): the
/// generated handler in the interpreter at the published instruction times, its characters and their times taken from
/// the simulated port, against the reference model's reply.
/// </summary>
public sealed class ReplyChunkTests
{
    private static readonly Station Two = new(2);
    private static readonly HandlerOptions Cpu224 = new() { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2 };

    private static ReadItem[] TwentyItems => [.. Enumerable.Range(0, 20).Select(i => new ReadItem(ProtocolArea.V, i * 5, i == 19 ? 1 : 4))];

    private static byte[] Read116(byte sequence) => RequestCodec.Encode(new ReadRequest(Two, sequence, [new ReadItem(ProtocolArea.V, 0, 116)]));

    [Fact]
    public void ReadOfOneItem116Bytes_LeavesInSeveralChunksBeforeTheCheckEnds_TheirCharactersTheReferenceReply()
    {
        var rig = new ReplyChunkRig(Cpu224, TimeSpan.FromMilliseconds(5));

        var served = rig.Serve(Read116(1));

        served.Sent.Should().HaveLength(250).And.Be(served.Expected);
        served.Chunks.Should().BeGreaterThan(5, "the check takes 18 passes of 14 characters, and the wire at 9600 baud is slower than it");
        served.FirstCharacterStart(rig.Line.CharacterTime).Should().BeLessThan(served.CheckDone - TimeSpan.FromMilliseconds(100));
        served.ReceivingBeforeEnd.Should().BeFalse("RCV is armed again only after the chunk that ends with the '>'");
    }

    [Fact]
    public void ReadListOf20Items_LeavesInSeveralChunksBeforeTheCheckEnds_TheirCharactersTheReferenceReply()
    {
        var rig = new ReplyChunkRig(Cpu224, TimeSpan.FromMilliseconds(5));
        var define = rig.Serve(RequestCodec.Encode(new DefineListRequest(Two, 1, 1, [.. TwentyItems])));

        var served = rig.Serve(RequestCodec.Encode(new ReadListRequest(Two, 2, 1)));

        define.Sent.Should().HaveLength(18).And.Be(define.Expected);
        define.Chunks.Should().Be(1, "a reply whose check takes one pass is one chunk");
        served.Sent.Should().HaveLength(172).And.Be(served.Expected);
        served.Chunks.Should().BeGreaterThan(3);
        served.FirstCharacterStart(rig.Line.CharacterTime).Should().BeLessThan(served.CheckDone);
    }

    /// <summary>
    /// The user's program times are chosen so that a transmit complete falls inside OP_PANEL between the publish of
    /// COVERED and the test of OP_STOP bit 2: at 1.013 ms right after the publish, at 1.299 ms right before the bit is
    /// read (found by trying times in 13 us steps; the test proves the routine did interrupt there).
    /// </summary>
    [Theory]
    [InlineData(1013)]
    [InlineData(1299)]
    public void TransmitCompleteBetweenThePublishAndTheIdleTest_NoCharacterSentTwiceOrLost(int userProgramUs)
    {
        var rig = new ReplyChunkRig(Cpu224, TimeSpan.FromTicks(userProgramUs * TimeSpan.TicksPerMicrosecond));
        var lines = rig.AwlText.Split("\r\n");
        var publish = Array.IndexOf(lines, "MOVD   AC2, VD8040") + 1;
        var idleTest = Array.FindIndex(lines, publish, l => l == "AN     V8059.2") + 1;

        var served = rig.Serve(Read116(2));

        rig.Runs.Should().Contain(r => r.Event == 9 && r.InterruptedLine > publish && r.InterruptedLine <= idleTest);
        served.Sent.Should().Be(served.Expected);
    }

    [Fact]
    public void LongUserScanAndLongReplyDelay_FirstChunkLateAndPausesBetweenChunks_ReplyStillWhole()
    {
        // A 40 ms reply delay lets several passes finish before the first chunk; 30 ms of user program per scan makes the
        // wire wait for the check after that first chunk.
        var rig = new ReplyChunkRig(Cpu224 with { ReplyDelayMs = 40 }, TimeSpan.FromMilliseconds(30));

        var served = rig.Serve(Read116(3));

        served.Sent.Should().Be(served.Expected);
        var gaps = served.Characters.Zip(served.Characters.Skip(1), (a, b) => b.At - a.At).ToList();
        gaps.Max().Should().BeGreaterThan(TimeSpan.FromMilliseconds(10), "the wire waits for the check between chunks");
        served.Chunks.Should().BeGreaterThan(3);
    }

    [Fact]
    public void RepliesCheckedInOnePass_OneChunkEach_AsTheReferenceAnswers()
    {
        var rig = new ReplyChunkRig(Cpu224, TimeSpan.FromMilliseconds(5));
        rig.Serve(RequestCodec.Encode(new DefineListRequest(Two, 4, 1, [new ReadItem(ProtocolArea.V, 0, 4)])));
        rig.Serve(RequestCodec.Encode(new ReadChangesRequest(Two, 5, 1, Full: true)));

        var error = rig.Serve(RequestCodec.Encode(new ReadRequest(Two, 6, [new ReadItem(ProtocolArea.V, 60000, 1)])));
        var idle = rig.Serve(RequestCodec.Encode(new ReadChangesRequest(Two, 7, 1, Full: false)));

        // 18 and 20 characters: 6 and 7 pairs of body characters, one pass of the check (7 pairs).
        error.Sent.Should().HaveLength(18).And.Be(error.Expected);
        error.Chunks.Should().Be(1);
        idle.Sent.Should().HaveLength(20).And.Be(idle.Expected);
        idle.Chunks.Should().Be(1);
    }

    [Fact]
    public void Identify_FourPassesOfTheCheck_LeavesInChunksAsTheReferenceAnswersBesideTheScanTimes()
    {
        var rig = new ReplyChunkRig(Cpu224, TimeSpan.FromMilliseconds(5));

        var identify = rig.Serve(RequestCodec.Encode(new IdentifyRequest(Two, 4)));

        // 62 characters, 28 pairs: 4 passes. SMW22-SMW26 (characters 31-42) and so the check differ from the reference's
        // copy taken before the request (DifferentialHarness masks them the same way).
        identify.Sent.Should().HaveLength(62);
        identify.Sent[..31].Should().Be(identify.Expected[..31]);
        identify.Sent[43..57].Should().Be(identify.Expected[43..57]);
        identify.Chunks.Should().BeInRange(1, 4);
    }

    [Fact]
    public void RequestArrivingDuringTheReply_NotReceivedUntilTheLastChunk_TheSameRequestAfterwardsIsAnswered()
    {
        var rig = new ReplyChunkRig(Cpu224, TimeSpan.FromMilliseconds(5));
        var retry = RequestCodec.Encode(new IdentifyRequest(Two, 6));

        var served = rig.Serve(Read116(7), during: retry);
        var after = rig.Serve(retry);

        served.Sent.Should().Be(served.Expected, "the reply goes on whole; the request on the bus meanwhile is not received");
        served.ReceivingBeforeEnd.Should().BeFalse();
        after.Sent.Should().HaveLength(62).And.StartWith("<020681");
    }

    [Fact]
    public void Stop_ExecutedAfterTheReplysLastCharacter()
    {
        var rig = new ReplyChunkRig(Cpu224 with { AllowStop = true }, TimeSpan.FromMilliseconds(5));

        var served = rig.Serve(RequestCodec.Encode(new StopRequest(Two, 8)));

        served.Sent.Should().HaveLength(18).And.Be(served.Expected);
        rig.Plc.Mode.Should().Be(Simulator.Reference.OperatingMode.Stop);
        rig.Plc.Fault!.Code.Should().Be("Stop");
        rig.LastScanStart.Should().BeGreaterThan(served.Characters[^1].At, "the scan that executed STOP began after the '>' had left");
    }
}
