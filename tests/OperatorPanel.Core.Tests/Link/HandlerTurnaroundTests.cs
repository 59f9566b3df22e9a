using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Link;

public sealed class HandlerTurnaroundTests
{
    private static readonly Station One = new(1);

    [Fact]
    public void ScansFor_ReadChangesOfLists_CountsOneComparisonPerListOfTheMaskBesidesTheFrames()
    {
        var frames = HandlerTurnaround.ScansFor(ProtocolLimits.RequestChars(1), ProtocolLimits.ReplyChars(ProtocolLimits.MaxReplyPayload));

        HandlerTurnaround.ScansFor(new ReadChangesOfListsRequest(One, ReadChangesOfListsRequest.MaskOf([1, 3])), ProtocolLimits.RequestChars(1))
            .Should().Be(frames + (2 * HandlerTurnaround.ChangeComparisonScans)).And.Be(5 + 3 + 43 + 70);
        HandlerTurnaround.ScansFor(new ReadChangesOfListsRequest(One, ProtocolLimits.ListMaskBits), ProtocolLimits.RequestChars(1))
            .Should().Be(frames + (4 * HandlerTurnaround.ChangeComparisonScans));
    }
}
