using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>How the PC cuts ranges into list items whose 4-byte windows stay inside their areas, and patches CHANGES by slot.</summary>
public sealed class V3ListPlanTests
{
    private static readonly Func<ProtocolArea, int> Cpu224 = ListPlan.AreaBytesOf(CpuProfiles.For(CpuModel.Cpu224));

    [Fact]
    public void TryMake_LongRange_CutFromItsEndSoEveryWindowStaysInTheRange()
    {
        ListPlan.TryMake([new ReadItem(ProtocolArea.M, 22, 10)], HandlerShape.Full, Cpu224, out var plan).Should().BeTrue();

        plan.Items.Take(3).Should().Equal(new ReadItem(ProtocolArea.M, 22, 2), new ReadItem(ProtocolArea.M, 24, 4), new ReadItem(ProtocolArea.M, 28, 4));
        (plan.Places[0], plan.DataBytes).Should().Be((0, 10 + 5), "the range's bytes in order, then 5 fillers to a group of 8");
    }

    [Fact]
    public void TryMake_GroupFilledUp_WithOneByteItemsOfIB12ThatTheHandlerServes()
    {
        ListPlan.TryMake([new ReadItem(ProtocolArea.V, 100, 4)], HandlerShape.Full, Cpu224, out var plan).Should().BeTrue();

        plan.Items.Skip(1).Should().Equal(Enumerable.Repeat(new ReadItem(ProtocolArea.I, 12, 1), 7),
            "the handler serves no SM (the fillers read SMB6 before): IB12's window IB12-IB15 ends at the input image's end");
    }

    [Fact]
    public void TryMake_ShortRangeAtTheAreasEnd_WidenedBackToA4ByteItem()
    {
        ListPlan.TryMake([new ReadItem(ProtocolArea.Q, 0, 1), new ReadItem(ProtocolArea.Q, 14, 2)], HandlerShape.Full, Cpu224, out var plan).Should().BeTrue();

        plan.Items[1].Should().Be(new ReadItem(ProtocolArea.Q, 12, 4), "QB14's window QB14-QB17 would pass QB15");
        plan.Places.Should().Equal(0, 1 + 2);
    }

    [Fact]
    public void TryApply_Changes_EachEntryPatchesItsItemsBytesOnly()
    {
        ListPlan.TryMake([new ReadItem(ProtocolArea.V, 10, 1), new ReadItem(ProtocolArea.V, 20, 3)], HandlerShape.Full, Cpu224, out var plan).Should().BeTrue();
        var known = new byte[plan.DataBytes];
        var reply = new Reply(ReplyStatus.Changes, 0, [1, 0xA1, 0xA2, 0xA3, 0xA4]);

        ListReply.TryRead(reply, plan, out var list).Should().BeTrue();
        list.TryApply(known, plan, out var data).Should().BeTrue();

        data.Take(5).Should().Equal([0, 0xA1, 0xA2, 0xA3, 0], "slot 1 (VB20, 3 bytes) starts at data byte 1; its window's fourth byte is not in the list");
    }

    [Fact]
    public void TryRead_EntryForASlotPastTheList_Refused()
    {
        ListPlan.TryMake([new ReadItem(ProtocolArea.V, 10, 4)], HandlerShape.Full, Cpu224, out var plan).Should().BeTrue();

        ListReply.TryRead(new Reply(ReplyStatus.Changes, 0, [8, 1, 2, 3, 4]), plan, out _).Should().BeFalse("the list has 8 slots, 0-7");
    }
}
