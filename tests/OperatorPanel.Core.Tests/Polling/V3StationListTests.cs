using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Polling.Readers;
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
            list.Slice(data, index, bytes).Should().Equal(data.Skip(offset).Take(bytes), "frame {0}'s bytes follow the frames before it", index);
            offset += bytes;
        }
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
