using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>The list rules of docs/protocol.md ("Lists"): each list's ATH below the floor, tail plus the largest reply within 255, and plain READs that keep a tail.</summary>
public sealed class ProtocolLimitsTests
{
    [Theory]
    [InlineData(new[] { 20 }, new[] { 81 }, true)]            // 80 + 174 = 254
    [InlineData(new[] { 20, 2 }, new[] { 81, 2 }, false)]     // 88 + 174 = 262
    [InlineData(new[] { 1 }, new[] { 119 }, true)]            // 4 + 250 = 254
    [InlineData(new[] { 10, 10 }, new[] { 60, 60 }, true)]    // 11 + 80 < 216 - 40; 80 + 132 = 212
    [InlineData(new[] { 1, 1, 1, 1, 1 }, new[] { 1, 1, 1, 1, 1 }, false)] // five lists
    [InlineData(new[] { 5, 20 }, new[] { 5, 20 }, false)]     // list 2's ATH: 11 + 160 >= 236 - 80
    [InlineData(new[] { 20, 5 }, new[] { 20, 5 }, true)]      // list 2's ATH: 11 + 40 < 176 - 20; 100 + 52 <= 255
    public void ListsFit_TailPlusLargestReply_AtMost255(int[] items, int[] data, bool fits)
    {
        ProtocolLimits.ListsFit(items.Zip(data)).Should().Be(fits);
    }

    [Theory]
    [InlineData(0, 20, 81, true)]    // no lists: any valid READ
    [InlineData(80, 2, 2, true)]     // the reference line's second frame next to its first frame's list
    [InlineData(80, 1, 119, false)]  // reply 250 > 175 - 4
    [InlineData(80, 1, 79, true)]    // reply 170 <= 171
    [InlineData(80, 1, 80, false)]   // reply 172 > 171
    [InlineData(160, 10, 8, false)]  // 9 + 80 >= 96 - 40: the descriptors' ATH would overlap its source
    public void ReadKeepsLists_AgainstATail_FollowsTheThreeRules(int tail, int items, int data, bool keeps)
    {
        ProtocolLimits.ReadKeepsLists(tail, items, data).Should().Be(keeps);
    }
}
