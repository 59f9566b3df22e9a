using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Polling.Readers;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>How a v3 station's list is laid out from the plan's frames: which frames it holds and where their bytes lie.</summary>
public sealed class V3StationListTests
{
    private static readonly Station Two = new(2);

    [Fact]
    public void Layout_FramesFitTheFullHandler_EveryFrameInTheListInPlanOrder()
    {
        var plan = Plan("VB100", "MW4", "QB0", "IB1");

        var list = new V3StationList(plan, Two, HandlerShape.Full);

        list.Frames.Should().Equal(Enumerable.Range(0, plan.Frames.Length));
        list.Plan!.DataBytes.Should().BeGreaterThanOrEqualTo(plan.Frames.Sum(f => f.DataBytes));
        var data = Enumerable.Range(0, list.Plan.DataBytes).Select(b => (byte)b).ToImmutableArray();
        var offset = 0;
        foreach (var index in list.Frames)
        {
            var bytes = plan.Frames[index].DataBytes;
            list.Slice(data, index).Should().Equal(data.Skip(offset).Take(bytes), "frame {0}'s bytes follow the frames before it", index);
            offset += bytes;
        }
    }

    [Fact]
    public void Layout_RangesWidenedBackwardAtTheirAreasEnd_EachTakesItsOwnBytesFromItsItem()
    {
        // QW14 and MW30 end their areas on a CPU 224 (16 Q bytes, 32 M bytes): each is widened to the 4-byte item that
        // ends with it (Q12/4, M28/4), so its bytes are the last 2 of its item, not the 2 after the range before it.
        var plan = Plan("QW14", "MW30");
        var cpu = CpuProfiles.For(CpuModel.Cpu224);

        var list = new V3StationList(plan, Two, HandlerShape.Full, ListPlan.AreaBytesOf(cpu));

        list.Plan!.Items.Take(2).Select(i => (i.Area, i.Offset, i.Length)).Should().Equal((ProtocolArea.Q, 12, 4), (ProtocolArea.M, 28, 4));
        byte[] q = [0x12, 0x13, 0x14, 0x15], m = [0x28, 0x29, 0x30, 0x31];
        var data = q.Concat(m).Concat(Enumerable.Repeat((byte)0x20, list.Plan.DataBytes - 8)).ToImmutableArray();
        var slices = list.Frames.SelectMany(index => list.Slice(data, index)).ToArray();
        slices.Should().Equal(new byte[] { 0x14, 0x15, 0x30, 0x31 }, "QW14 = QB14-QB15 and MW30 = MB30-MB31, whether in one frame or two");
    }

    [Fact]
    public void Layout_FrameTooBigForTheHandlersList_LeftOutForRead()
    {
        var plan = Plan("VD100", "VD104", "VD108", "VD112", "VD116", "MB4");
        var small = new HandlerShape(136, 8, 8);

        var list = new V3StationList(plan, Two, small);

        plan.Frames.Should().ContainSingle("the planner packs the six blocks in one frame of 21 bytes");
        list.Frames.Should().BeEmpty();
        list.Plan.Should().BeNull();
        new V3StationList(plan, Two, HandlerShape.Full).Frames.Should().Equal(0);
    }

    private static PollPlan Plan(params string[] addresses) => PollPlanner.Build(
        addresses.Select(a => new WatchedItem(Two, PlcAddress.Parse(a))),
        new Dictionary<Station, CpuProfile> { [Two] = CpuProfiles.For(CpuModel.Cpu224) });
}
