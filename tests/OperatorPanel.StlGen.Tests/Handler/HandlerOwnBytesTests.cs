using System.Collections.Immutable;
using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.StlGen.Handler;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Differential;

namespace OperatorPanel.StlGen.Tests.Handler;

/// <summary>
/// The handler's own V bytes (buffer and work bytes, docs/protocol-v2.md "Work bytes") are refused to WRITE and WRITE
/// BIT with error 03 by the generated STL and by the reference model alike, and the station keeps answering.
/// </summary>
public sealed class HandlerOwnBytesTests
{
    private static readonly HandlerOptions Options = new() { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2 };

    /// <summary>
    /// Buffer byte 0 (count) and 1 ('&lt;'); byte 11, the WRITE's own LENGTH: before the check, writing FF there made the
    /// read-back HTA 510 characters past the buffer and the CPU stopped on the indirect address (silent until restarted);
    /// the stored-list tail, LAST_FREE, STEP, the last saved accumulator byte, REQCHECK, the CRC and the last work byte.
    /// </summary>
    public static TheoryData<int> HandlerOffsets =>
    [
        0, 1, 11, 200, 255, HandlerLayout.LastFree, HandlerLayout.Step, HandlerLayout.Save + 15, HandlerLayout.ReqCheck, HandlerLayout.Crc + 1,
        HandlerMemory.BufferBytes + HandlerLayout.WorkBytes - 1,
    ];

    [Theory]
    [MemberData(nameof(HandlerOffsets))]
    public void Write_IntoTheHandlersOwnBytes_IsRefusedWithError03AndTheStationStillAnswers(int offset)
    {
        var harness = new DifferentialHarness(Options, new Random(9));
        var at = Options.EffectiveBufferStart + offset;

        PlcRequest writeRequest = new WriteBlockRequest(new Station(2), 1, ProtocolArea.V, at, [0xFF]);
        PlcRequest bitRequest = new WriteBitRequest(new Station(2), 2, ProtocolArea.V, at, 0, false);
        var write = Send(harness, writeRequest);
        var bit = Send(harness, bitRequest);
        var identify = Send(harness, new IdentifyRequest(new Station(2), 3));

        write.Stl.Should().Be(write.Reference).And.Be(ErrorReply(writeRequest));
        bit.Stl.Should().Be(bit.Reference).And.Be(ErrorReply(bitRequest));
        identify.Stl.Should().StartWith("<020381").And.Be(identify.Reference);
    }

    [Fact]
    public void Write_BlockReachingIntoTheBuffer_IsRefusedWhole()
    {
        var harness = new DifferentialHarness(Options, new Random(9));
        harness.Poke(ProtocolArea.V, Options.EffectiveBufferStart - 2, 0xAA);

        PlcRequest request = new WriteBlockRequest(new Station(2), 1, ProtocolArea.V, Options.EffectiveBufferStart - 2, [1, 2, 3]);
        var write = Send(harness, request);

        write.Stl.Should().Be(write.Reference).And.Be(ErrorReply(request));
        harness.Interpreted(ProtocolArea.V)[Options.EffectiveBufferStart - 2].Should().Be(0xAA, "nothing of a refused block is written");
    }

    [Fact]
    public void Write_EndingJustBeforeTheBuffer_IsConfirmed()
    {
        var harness = new DifferentialHarness(Options, new Random(9));

        var write = Send(harness, new WriteBlockRequest(new Station(2), 1, ProtocolArea.V, Options.EffectiveBufferStart - 2, [0x12, 0x34]));

        write.Stl.Should().Be(write.Reference).And.StartWith("<02018300");
    }

    [Theory]
    [InlineData(CpuModel.Cpu221)]
    [InlineData(CpuModel.Cpu222)]
    [InlineData(CpuModel.Cpu224)]
    [InlineData(CpuModel.Cpu224XP)]
    [InlineData(CpuModel.Cpu226)]
    public void ReferenceModel_DefaultHandlerBytes_AreWhereTheGeneratorPutsThem(CpuModel model)
    {
        var cpu = CpuProfiles.For(model);
        var config = new HandlerConfig(new Station(1), cpu);
        var stats = HandlerGenerator.Generate(new HandlerOptions { Protocol = 2, Cpu = cpu }).Stats!;

        (config.BufferStart, config.BufferStart + config.HandlerVBytes - 1).Should().Be((stats.FirstVByte, stats.LastVByte));
    }

    private static (string Stl, string Reference) Send(DifferentialHarness harness, PlcRequest request) =>
        harness.Exchange([WireChunk.Now(RequestCodec.Encode(request))]);

    /// <summary>Error 03 to <paramref name="request"/>: STATUS, then REQCHECK, the CRC of the request's characters.</summary>
    private static string ErrorReply(PlcRequest request)
    {
        FrameCodec.TryGetCheck(RequestCodec.Encode(request), out var check).Should().BeTrue();
        var command = (byte)((byte)request.Command | FreeportFrame.ReplyBit);
        return Encoding.ASCII.GetString(FrameCodec.Encode(new FreeportFrame(
            2, request.Sequence, command, ImmutableArray.Create((byte)ProtocolError.NotWritable, (byte)(check >> 8), (byte)check))));
    }
}
