using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.TestKit.ProtocolDoc;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>
/// The worked examples of docs/protocol.md section 5 (protocol v3) are frames a stranger copies into a client or a
/// handler: each request must be a valid v3 request (LEN, check, STATION, CMD) and each reply the valid reply to its
/// request (its check, STATUS bit 7, REQCHECK = the request's last two bytes), except the frame the text itself calls
/// corrupted. (That every reply is the reference model's answer: Simulator.Tests' ReferenceHandlerSection5Tests; the
/// generated handler's: StlGen.Tests' V3Section5Tests.)
/// </summary>
public sealed class V3DocExamplesTests
{
    [Fact]
    public void Section5_EveryRequestAndReply_DecodesAndEveryReplyAnswersItsRequest()
    {
        var frames = ProtocolSection5.Steps().Where(s => s.Request is not null && !s.Corrupted).ToList();

        frames.Should().HaveCountGreaterThan(20, "section 5 has IDENTIFY, READ, WRITE, WRITE BITS, the list and the refusals");
        foreach (var step in frames)
        {
            Codec.TryDecodeRequest(step.Request!, out _, out var requestError).Should().BeTrue($"{step.Line}: request {requestError}");
            if (step.Reply is not null)
            {
                Codec.TryDecodeReplyTo(step.Reply, step.Request!, out _, out var replyError).Should().BeTrue($"{step.Line}: reply {replyError}");
            }
        }
    }

    [Fact]
    public void Section5_TheFrameWithOneBitFlipped_FailsItsCheck()
    {
        var flipped = ProtocolSection5.Steps().Where(s => s.Corrupted).ToList();

        flipped.Should().ContainSingle();
        Codec.TryDecodeRequest(flipped[0].Request!, out _, out var error).Should().BeFalse();
        error.Should().Be(DecodeError.CheckMismatch);
        flipped[0].Reply.Should().BeNull("the text says silence");
    }

    [Fact]
    public void Section5_RepeatedItems_AreExpandedToTheirLen()
    {
        var repeated = ProtocolSection5.Steps().Where(s => s.Line.Contains("(x", StringComparison.Ordinal)).ToList();

        repeated.Should().HaveCount(2, "DEFINE LIST of 7 items and of 8 x MB31");
        repeated.Select(s => s.Request!.Length).Should().Equal(8 + 28, 8 + 32);
        repeated.Should().OnlyContain(s => s.Request![1] == s.Request.Length, "LEN counts the repeated items");
    }
}
