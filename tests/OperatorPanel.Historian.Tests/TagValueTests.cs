using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Historian.Tests;

/// <summary>Stored integers back into the numbers and texts the panel shows.</summary>
public sealed class TagValueTests
{
    [Theory]
    [InlineData("VW150", DisplayFormat.Signed, "FFFF", -1)]
    [InlineData("VW150", DisplayFormat.Unsigned, "FFFF", 65535)]
    [InlineData("VD120", DisplayFormat.Float, "3FC00000", 1.5)]
    [InlineData("VB160", DisplayFormat.Hex, "2A", 42)]
    [InlineData("M0.0", DisplayFormat.Bool, "01", 1)]
    [InlineData("VD100", DisplayFormat.Signed, "80000000", -2147483648)]
    public void ToNumber_StoredBytes_IsTheShownNumber(string address, DisplayFormat format, string hex, double expected)
    {
        var stored = TagValue.ToStored([.. Convert.FromHexString(hex)]);

        TagValue.ToNumber(stored, PlcAddress.Parse(address), format).Should().Be(expected);
    }

    [Fact]
    public void ToRaw_Stored_RoundTrips()
    {
        var raw = TagValue.ToRaw(TagValue.ToStored([0x12, 0x34, 0x56, 0x78]), PlcAddress.Parse("VD4"));

        raw.Should().Equal(0x12, 0x34, 0x56, 0x78);
    }

    [Fact]
    public void ToText_Hex_IsWrittenAsTheManualWritesConstants()
    {
        TagValue.ToText(0x2A, PlcAddress.Parse("VB160"), DisplayFormat.Hex).Should().Be("16#2A");
    }
}
