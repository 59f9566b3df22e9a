using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using static OperatorPanel.Simulator.Tests.Reference.Exchange;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>
/// What RCV hands the handler and what the handler makes of it (docs/protocol-v2.md, "Processing order", steps 1-2): the
/// last '&lt;' restarts the frame, the receive interrupt's early silence looks at the first '&lt;', and invalidation 1
/// counts every received character.
/// </summary>
public sealed class ReferencePlcReceiveTests
{
    private static readonly Station One = new(1);

    private readonly ReferencePlc _plc = new(new HandlerConfig(One, CpuProfiles.For(CpuModel.Cpu224)));

    private byte[]? Receive(string prefix, PlcRequest request) =>
        _plc.HandleFrame([.. Encoding.ASCII.GetBytes(prefix), .. RequestCodec.Encode(request)]);

    [Theory]
    [InlineData("<0107")] //     a frame for this station cut off by noise
    [InlineData("<01")]
    [InlineData("<0100")]
    public void Receive_CutOffFrameBeforeANewStart_AnswersTheFrameFromTheLastStart(string remains)
    {
        var request = new IdentifyRequest(One, 0x31);

        var reply = Receive(remains, request);

        ResponseCodec.TryDecode(reply, request, out var response, out var error).Should().BeTrue(error.ToString());
        response.Should().BeOfType<IdentifyResponse>();
    }

    [Theory]
    [InlineData("<0211")] //     another station's cut-off frame: the stated cost, this frame is missed once
    [InlineData("<02")]
    [InlineData("<01078")] //    a cut-off reply (CMD 8x)
    [InlineData("<0107F")]
    [InlineData("<0x")] //       not even hex
    public void Receive_FirstStartNotARequestForThisStation_IsSilentEvenWhenTheLastFrameIs(string remains)
    {
        Receive(remains, new IdentifyRequest(One, 0x32)).Should().BeNull();
    }

    [Fact]
    public void Receive_CharactersBeforeTheLastStart_CountForTheListTail()
    {
        // A list of 20 single bytes: floor 176. The frame itself is 14 characters, the message 14 + 165 = 179 > 175.
        Send(_plc, "01 01 05", "01 14" + string.Concat(Enumerable.Range(0, 20).Select(i => $"04{i:X4}01")))!.Payload.Should().Equal(0x00);

        var reply = Receive("<01" + new string('0', 162), new ReadListRequest(One, 0x33, 1));

        FrameCodec.TryDecode(reply, out var frame, out _).Should().BeTrue();
        frame.Payload[0].Should().Be((byte)ProtocolError.ListNotDefined);
    }

    [Fact]
    public void Receive_EndedByCountWithoutEnd_ClearsTheListsItReached()
    {
        var port = new SimulatedPlcPort(_plc);
        Send(_plc, "01 01 05", "01 01 03000201")!.Payload.Should().Equal(0x00);

        port.Feed(Encoding.ASCII.GetBytes("<" + new string('0', 254))).Should().BeEmpty();

        port.DroppedReceives.Should().Be(1);
        _plc.Lists.IsDefined(1).Should().BeFalse();
    }
}
