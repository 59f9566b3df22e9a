using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V1;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>The v1 IDENTIFY probe (docs/protocol-v2.md, "Version 1 handlers"), on the frames of the v1 document's example 5.1.</summary>
public sealed class V1IdentifyProbeTests
{
    private const string V1Request = "<01070107>";

    /// <summary>A v1 handler's IDENTIFY reply: protocol 01, CPU 224, ...; BCC 73 (v1 document, example 5.1).</summary>
    private const string V1Reply = "<01078100010103013C7705200100030002000973>";

    private static readonly Station One = new(1);

    [Fact]
    public void Encode_Station1Sequence7_IsTheV1Frame()
    {
        Encoding.ASCII.GetString(V1IdentifyProbe.Encode(One, 0x07)).Should().Be(V1Request);
    }

    [Fact]
    public void TryDecodeReply_V1HandlersReply_GivesProtocolVersion1()
    {
        V1IdentifyProbe.TryDecodeReply(Encoding.ASCII.GetBytes(V1Reply), One, 0x07, out var version).Should().BeTrue();

        version.Should().Be(1);
    }

    [Theory]
    [InlineData("<01078100010103013C7705200100030002000972>")] // BCC off by one bit
    [InlineData("<01088100010103013C770520010003000200097C>")] // another sequence (BCC recomputed)
    [InlineData("<01078400010103013C7705200100030002000976>")] // not an IDENTIFY reply
    [InlineData("<010781050A>")] //                            an error reply
    [InlineData("<010701dl`l>")] //                            a v2 frame
    public void TryDecodeReply_AnythingElse_IsNotAV1Reply(string frame)
    {
        V1IdentifyProbe.TryDecodeReply(Encoding.ASCII.GetBytes(frame), One, 0x07, out _).Should().BeFalse();
    }

    [Fact]
    public void V2Codec_RefusesTheV1Frames_SoNeitherVersionAnswersTheOther()
    {
        FrameCodec.TryDecode(Encoding.ASCII.GetBytes(V1Request), out _, out var requestError).Should().BeFalse();
        FrameCodec.TryDecode(Encoding.ASCII.GetBytes(V1Reply), out _, out var replyError).Should().BeFalse();

        (requestError, replyError).Should().Be((FrameError.TooShort, FrameError.BadCheckCharacter), "a v1 body ends in a hex BCC, never in check characters");
    }
}
