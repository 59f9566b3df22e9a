using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Core.Tests.Values;

public sealed class ValueFormatInferenceTests
{
    [Theory]
    [InlineData("1", AccessWidth.Bit, DisplayFormat.Bool)]
    [InlineData("on", AccessWidth.Bit, DisplayFormat.Bool)]
    [InlineData("42", AccessWidth.Word, DisplayFormat.Unsigned)]
    [InlineData("+42", AccessWidth.Word, DisplayFormat.Unsigned)]
    [InlineData("-5", AccessWidth.Word, DisplayFormat.Signed)]
    [InlineData("16#FF", AccessWidth.Byte, DisplayFormat.Hex)]
    [InlineData("0xff", AccessWidth.Byte, DisplayFormat.Hex)]
    [InlineData("-16#10", AccessWidth.Word, DisplayFormat.Hex)]
    [InlineData("2#1010", AccessWidth.Byte, DisplayFormat.Binary)]
    [InlineData("12.5", AccessWidth.DoubleWord, DisplayFormat.Float)]
    [InlineData("1e3", AccessWidth.DoubleWord, DisplayFormat.Float)]
    [InlineData("'AB12'", AccessWidth.DoubleWord, DisplayFormat.Ascii)]
    [InlineData("\"OK\"", AccessWidth.Word, DisplayFormat.Ascii)]
    [InlineData("", AccessWidth.Byte, DisplayFormat.Unsigned)]
    public void Infer_Notation_PicksTheFormat(string text, AccessWidth width, DisplayFormat expected) =>
        ValueFormatInference.Infer(text, width).Should().Be(expected);
}
