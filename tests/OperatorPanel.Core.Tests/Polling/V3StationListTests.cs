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

    /// <summary>
    /// Any watched set, ends of areas included: the list data the handler sends (each item's bytes from memory, in item
    /// order) sliced per frame gives exactly the bytes of that frame's ranges.
    /// </summary>
    [Theory]
    [InlineData(CpuModel.Cpu221)]
    [InlineData(CpuModel.Cpu224)]
    [InlineData(CpuModel.Cpu226)]
    public void Slice_RandomWatchedSetsNearTheEndsOfEveryArea_EveryFrameGetsItsOwnBytes(CpuModel model)
    {
        var cpu = CpuProfiles.For(model);
        var areaBytes = ListPlan.AreaBytesOf(cpu);
        ProtocolArea[] areas = [ProtocolArea.I, ProtocolArea.Q, ProtocolArea.M, ProtocolArea.V];
        string[] prefixes = ["I", "Q", "M", "V"];
        var checkedFrames = 0;
        for (var seed = 0; seed < 150; seed++)
        {
            var random = new Random(seed);
            var memory = areas.ToDictionary(a => a, a => Enumerable.Range(0, areaBytes(a)).Select(_ => (byte)random.Next(256)).ToArray());
            var addresses = Enumerable.Range(0, random.Next(1, 12)).Select(_ =>
            {
                var k = random.Next(areas.Length);
                var (width, letter) = random.Next(3) switch { 0 => (1, "B"), 1 => (2, "W"), _ => (4, "D") };
                var size = areaBytes(areas[k]) - (areas[k] == ProtocolArea.V ? HandlerShape.Full.VBytes : 0);
                var offset = random.Next(2) == 0 ? size - width - random.Next(3) : random.Next(size - width);
                return $"{prefixes[k]}{letter}{Math.Max(offset, 0)}";
            }).Distinct().ToArray();
            var plan = PollPlanner.Build(addresses.Select(a => new WatchedItem(Two, PlcAddress.Parse(a))), new Dictionary<Station, CpuProfile> { [Two] = cpu });

            var list = new V3StationList(plan, Two, HandlerShape.Full, areaBytes);

            var data = list.Plan!.Items.SelectMany(i => memory[i.Area].Skip(i.Offset).Take(i.Length)).ToImmutableArray();
            foreach (var index in list.Frames)
            {
                var frame = plan.Frames[index];
                list.Slice(data, index).Should().Equal(frame.Items.SelectMany(i => memory[i.Area].Skip(i.Offset).Take(i.Length)), "seed {0}, {1}, frame {2}", seed, string.Join(" ", addresses), index);
                checkedFrames++;
            }
        }

        checkedFrames.Should().BeGreaterThanOrEqualTo(150, "every seed's list holds at least one frame");
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
