using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>
/// The limits of docs/protocol-v2.md ("Limits", "Lists"): frame sizes, each list's ATH below the floor, tail plus the
/// longest list reply (READ CHANGES FULL, 20 + 2D) within 255, and plain READs and WRITEs that keep a tail.
/// </summary>
public sealed class ProtocolLimitsTests
{
    [Theory]
    [InlineData(new[] { 20 }, new[] { 77 }, true)]            // 80 + 174 = 254
    [InlineData(new[] { 20 }, new[] { 78 }, false)]           // 80 + 176 = 256: a valid READ, but READ CHANGES FULL is 2 longer
    [InlineData(new[] { 20, 2 }, new[] { 77, 2 }, false)]     // 88 + 174 = 262
    [InlineData(new[] { 1 }, new[] { 115 }, true)]            // 4 + 250 = 254
    [InlineData(new[] { 1 }, new[] { 116 }, false)]           // 4 + 252 = 256
    [InlineData(new[] { 1 }, new[] { 117 }, false)]           // not even a READ
    [InlineData(new[] { 10, 10 }, new[] { 60, 60 }, true)]    // 11 + 80 < 216 - 40; 80 + 132 = 212
    [InlineData(new[] { 1, 1, 1, 1, 1 }, new[] { 1, 1, 1, 1, 1 }, false)] // five lists
    [InlineData(new[] { 5, 20 }, new[] { 5, 20 }, false)]     // list 2's ATH: 11 + 160 >= 236 - 80
    [InlineData(new[] { 20, 5 }, new[] { 20, 5 }, true)]      // list 2's ATH: 11 + 40 < 176 - 20; 100 + 52 <= 255
    public void ListsFit_TailPlusLargestReply_AtMost255(int[] items, int[] data, bool fits)
    {
        ProtocolLimits.ListsFit(items.Zip(data)).Should().Be(fits);
    }

    [Theory]
    [InlineData(0, 20, 78, true)]    // no lists: any valid READ
    [InlineData(80, 2, 2, true)]     // a short frame next to a 20-item list
    [InlineData(80, 1, 116, false)]  // reply 250 > 175 - 4
    [InlineData(80, 1, 76, true)]    // reply 170 <= 171
    [InlineData(80, 1, 77, false)]   // reply 172 > 171
    [InlineData(160, 10, 8, false)]  // 9 + 80 >= 96 - 40: the descriptors' ATH would overlap its source
    public void ReadKeepsLists_AgainstATail_FollowsTheThreeRules(int tail, int items, int data, bool keeps)
    {
        ProtocolLimits.ReadKeepsLists(tail, items, data).Should().Be(keeps);
    }

    [Theory]
    [InlineData(80, 77, true)]   // request 20 + 154 = 174 <= 175
    [InlineData(80, 78, false)]  // 176 > 175
    [InlineData(0, 117, true)]   // the largest WRITE, 254 characters
    public void WriteKeepsLists_AgainstATail_ComparesTheRequestWithTheFloor(int tail, int data, bool keeps)
    {
        ProtocolLimits.WriteKeepsLists(tail, data).Should().Be(keeps);
    }

    [Fact]
    public void Limits_FollowFromTheFrameSizes()
    {
        (ProtocolLimits.RequestChars(0), ProtocolLimits.ReplyChars(0), ProtocolLimits.ListReplyChars(10)).Should().Be((12, 18, 40));
        ProtocolLimits.FrameChars(ProtocolLimits.MaxBodyBytes).Should().Be(254);
        ProtocolLimits.FrameChars(ProtocolLimits.MaxBodyBytes + 1).Should().BeGreaterThan(ProtocolLimits.MaxFrameChars);
        (ProtocolLimits.MaxReadData, ProtocolLimits.MaxWriteData).Should().Be((116, 117));
        ProtocolLimits.ReplyChars(ProtocolLimits.MaxReadData).Should().Be(250, "bytes 1-250: the one-item READ's reply ends before its descriptor at 252-255");
        ProtocolLimits.ReplyChars(ProtocolLimits.MaxReadData + 1).Should().Be(252);
        (ProtocolLimits.MaxReadDataFor(1), ProtocolLimits.MaxReadDataFor(2), ProtocolLimits.MaxReadDataFor(8), ProtocolLimits.MaxReadDataFor(20))
            .Should().Be((116, 114, 102, 78));
        (ProtocolLimits.MaxReadDataFor(0), ProtocolLimits.MaxReadDataFor(21)).Should().Be((0, 0));
    }
}
