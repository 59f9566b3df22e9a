using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Core.Tests.Values;

public sealed class TagValuesTests
{
    private static readonly ProjectTag Level = new("TankLevel", PlcAddress.Parse("VW150"), DisplayFormat.Signed, false, string.Empty)
    {
        Unit = "%",
        Scale = new TagScale(0, 1000, 0, 100),
    };

    private static readonly ProjectTag Recipe = new("RecipeNumber", PlcAddress.Parse("VB110"), DisplayFormat.Unsigned, true, string.Empty)
    {
        Range = new TagRange(1, 8),
    };

    [Theory]
    [InlineData(552, "55.2 %")]
    [InlineData(0, "0.0 %")]
    [InlineData(-10, "-1.0 %")]
    public void Format_ScaledTag_ShowsTheEngineeringValueWithOneStepsDigitsAndItsUnit(short raw, string text)
    {
        TagValues.Format(Level, [(byte)(raw >> 8), (byte)raw]).Should().Be(text);
    }

    [Fact]
    public void TryParse_ScaledValueWithOrWithoutUnit_GivesTheRawBytes()
    {
        TagValues.TryParse(Level, "55.2 %", out var bytes, out _).Should().BeTrue();
        bytes.Should().Equal(0x02, 0x28); // 552
        TagValues.TryParse(Level, "60", out bytes, out _).Should().BeTrue();
        bytes.Should().Equal(0x02, 0x58); // 600
    }

    [Theory]
    [InlineData("9", "RecipeNumber (VB110): 9 is outside its range 1..8")]
    [InlineData("0", "RecipeNumber (VB110): 0 is outside its range 1..8")]
    [InlineData("three", "RecipeNumber (VB110): 'three' is not a number")]
    public void TryParse_OutsideTheRangeOrNoNumber_IsRefusedNamingTheSymbol(string text, string message)
    {
        TagValues.TryParse(Recipe, text, out _, out var error).Should().BeFalse();
        error!.Message.Should().Be(message);
    }

    [Fact]
    public void TryParse_InsideTheRange_GivesTheByte()
    {
        TagValues.TryParse(Recipe, "8", out var bytes, out _).Should().BeTrue();
        bytes.Should().Equal(8);
    }

    [Theory]
    [InlineData("0..1000 -> 0..100", true)]
    [InlineData("-27648..27648 -> -100..100", true)]
    [InlineData("0..1000", false)]
    [InlineData("0..0 -> 0..1", false)]
    public void TagScale_TryParse_ReadsTheWizardsText(string text, bool ok)
    {
        TagScale.TryParse(text, out var scale, out _).Should().Be(ok);
        if (ok)
        {
            scale!.ToString().Should().Be(text);
        }
    }

    [Theory]
    [InlineData("1..8", 1.0, 8.0)]
    [InlineData("0..", 0.0, null)]
    [InlineData("..100", null, 100.0)]
    public void TagRange_TryParse_TakesOpenEnds(string text, double? min, double? max)
    {
        TagRange.TryParse(text, out var range, out _).Should().BeTrue();
        range.Should().Be(new TagRange(min, max));
        range!.ToString().Should().Be(text);
    }
}
