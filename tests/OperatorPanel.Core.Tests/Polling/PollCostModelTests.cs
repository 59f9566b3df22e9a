using OperatorPanel.Core.Polling;

namespace OperatorPanel.Core.Tests.Polling;

public sealed class PollCostModelTests
{
    [Theory]
    [InlineData(1, 116)]
    [InlineData(2, 114)]
    [InlineData(8, 102)]
    [InlineData(20, 78)]
    [InlineData(21, 0)] // more items than one READ may carry
    public void MaxDataFor_ItemCount_FollowsTheTwoDPlusFourNRule(int items, int expected)
    {
        PollCostModel.Default.MaxDataFor(items).Should().Be(expected);
    }

    [Theory]
    [InlineData(20, 78, true)]
    [InlineData(20, 79, false)]
    [InlineData(21, 21, false)]
    [InlineData(1, 116, true)]
    [InlineData(1, 117, false)]
    [InlineData(0, 0, false)]
    public void Fits_ItemsAndData_TrueOnlyWithinBothLimits(int items, int dataBytes, bool expected)
    {
        PollCostModel.Default.Fits(items, dataBytes).Should().Be(expected);
    }

    [Fact]
    public void MaxDataFor_LowerCustomCap_CapsTheRule()
    {
        var model = PollCostModel.Default with { MaxDataPerFrame = 64, MaxItemsPerFrame = 4 };

        (model.MaxDataFor(1), model.MaxDataFor(4), model.MaxDataFor(5)).Should().Be((64, 64, 0));
    }
}
