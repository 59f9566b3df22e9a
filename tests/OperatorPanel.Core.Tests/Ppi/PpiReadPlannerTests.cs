using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Core.Tests.Ppi;

public sealed class PpiReadPlannerTests
{
    [Fact]
    public void Plan_NearbyAddresses_MergeIntoOneItemPerArea()
    {
        var plan = PpiReadPlanner.Plan(Parse("I0.0", "IB1", "VW100", "VB104", "VD110", "M10.7"));

        plan.Requests.Should().ContainSingle();
        plan.Requests[0].Items.Should().Equal(
            S7Item.Bytes(S7Area.I, 0, 2), S7Item.Bytes(S7Area.M, 10, 1), S7Item.Bytes(S7Area.V, 100, 14));
        plan.Slices[PlcAddress.Parse("VD110")].Should().Be(new PpiSlice(0, 2, 10, 4));
        plan.Slices[PlcAddress.Parse("M10.7")].Should().Be(new PpiSlice(0, 1, 0, 1));
    }

    [Fact]
    public void Plan_GapLongerThanAnItemCosts_KeepsTwoItems()
    {
        var plan = PpiReadPlanner.Plan(Parse("VB0", "VB18"));

        plan.Requests[0].Items.Should().Equal(S7Item.Bytes(S7Area.V, 0, 1), S7Item.Bytes(S7Area.V, 18, 1));
    }

    [Fact]
    public void Plan_TwentyFiveScatteredBytes_SplitsAtTheItemLimitOfA240BytePdu()
    {
        var addresses = Enumerable.Range(0, 25).Select(i => PlcAddress.ForBytes(MemoryArea.V, i * 100, AccessWidth.Byte));

        var plan = PpiReadPlanner.Plan(addresses);

        plan.Requests.Select(r => r.Items.Length).Should().Equal(19, 6);
        plan.Requests.Should().OnlyContain(r => r.RequestPduLength <= 240 && r.AnswerPduLength <= 240);
    }

    [Fact]
    public void Plan_LongRunOfV_IsCutAtTheLongestItemAnswerThatFits()
    {
        var addresses = Enumerable.Range(0, 300).Select(i => PlcAddress.ForBytes(MemoryArea.V, i, AccessWidth.Byte));

        var plan = PpiReadPlanner.Plan(addresses);

        plan.Requests.Select(r => r.DataBytes).Should().Equal(222, 78);
        plan.Requests.Should().OnlyContain(r => r.AnswerPduLength <= 240);
        plan.Slices.Should().HaveCount(300);
    }

    [Fact]
    public void Plan_AnalogWords_AreWordItems()
    {
        var plan = PpiReadPlanner.Plan(Parse("AIW0", "AIW2", "AIW8"));

        plan.Requests[0].Items.Should().Equal(S7Item.Words(S7Area.AI, 0, 5));
        plan.Slices[PlcAddress.Parse("AIW8")].Should().Be(new PpiSlice(0, 0, 8, 2));
    }

    [Fact]
    public void Plan_UnreachableArea_IsRejectedWithItsReason()
    {
        // The panel's parser never yields L, but code can build one: the planner must still refuse it.
        var lb0 = PlcAddress.ForBytes(MemoryArea.L, 0, AccessWidth.Byte);

        var plan = PpiReadPlanner.Plan([lb0, PlcAddress.Parse("MB0")]);

        plan.Rejected.Should().ContainKey(lb0);
        plan.Slices.Keys.Should().Equal(PlcAddress.Parse("MB0"));
    }

    [Fact]
    public void Plan_SmallerPdu_PacksSmallerAnswers()
    {
        var addresses = Enumerable.Range(0, 100).Select(i => PlcAddress.ForBytes(MemoryArea.M, i % 32, AccessWidth.Byte))
            .Concat(Enumerable.Range(0, 100).Select(i => PlcAddress.ForBytes(MemoryArea.V, i, AccessWidth.Byte)));

        var plan = PpiReadPlanner.Plan(addresses, new PpiLimits { PduSize = 64 });

        plan.Requests.Should().OnlyContain(r => r.RequestPduLength <= 64 && r.AnswerPduLength <= 64);
        plan.DataBytes.Should().Be(132);
    }

    private static PlcAddress[] Parse(params string[] addresses) => [.. addresses.Select(PlcAddress.Parse)];
}
