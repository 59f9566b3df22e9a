using OperatorPanel.Simulator.Stl.Run;

namespace OperatorPanel.Simulator.Tests.Stl.Run;

public sealed class StlSettingTests
{
    [Theory]
    [InlineData("250ms", 250)]
    [InlineData("2s", 2_000)]
    [InlineData("1.5s", 1_500)]
    [InlineData("10m", 600_000)]
    [InlineData("0.5m", 30_000)]
    [InlineData("2h", 7_200_000)]
    [InlineData("0", 0)]
    public void TryParseTime_NumberAndUnit_GivesTheTime(string text, double milliseconds)
    {
        StlSetting.TryParseTime(text, out var time).Should().BeTrue();

        time.TotalMilliseconds.Should().Be(milliseconds);
    }

    [Theory]
    [InlineData("soon")]
    [InlineData("5")]
    [InlineData("25h")]
    [InlineData("-1s")]
    [InlineData("")]
    public void TryParseTime_NoUnitOrOverADay_IsRefused(string text) =>
        StlSetting.TryParseTime(text, out _).Should().BeFalse();
}
