using OperatorPanel.Core.Addressing;
using OperatorPanel.Stl;

namespace OperatorPanel.Stl.Tests;

public sealed class AwlOperandTests
{
    [Theory]
    [InlineData("I0.3", MemoryArea.I, AccessWidth.Bit, 0, 3)]
    [InlineData("VB100", MemoryArea.V, AccessWidth.Byte, 100, null)]
    [InlineData("SMW22", MemoryArea.SM, AccessWidth.Word, 22, null)]
    [InlineData("LD4", MemoryArea.L, AccessWidth.DoubleWord, 4, null)]
    [InlineData("L1.7", MemoryArea.L, AccessWidth.Bit, 1, 7)]
    [InlineData("AC1", MemoryArea.AC, AccessWidth.DoubleWord, 1, null)]
    [InlineData("T37", MemoryArea.T, AccessWidth.Word, 37, null)]
    [InlineData("C5", MemoryArea.C, AccessWidth.Word, 5, null)]
    [InlineData("HC0", MemoryArea.HC, AccessWidth.DoubleWord, 0, null)]
    [InlineData("AIW2", MemoryArea.AI, AccessWidth.Word, 2, null)]
    [InlineData("aqw0", MemoryArea.AQ, AccessWidth.Word, 0, null)]
    [InlineData("SB3", MemoryArea.S, AccessWidth.Byte, 3, null)]
    public void TryParse_Address_GivesAreaWidthOffsetBit(string text, MemoryArea area, AccessWidth width, int offset, int? bit)
    {
        AwlOperand.TryParse(text, out var operand, out _).Should().BeTrue();
        (operand!.Kind, operand.Area, operand.Width, operand.ByteOffset, operand.Bit).Should().Be((AwlOperandKind.Address, area, width, offset, bit));
    }

    [Theory]
    [InlineData("100", 100L)]
    [InlineData("-5", -5L)]
    [InlineData("16#3C", 0x3CL)]
    [InlineData("16#FFFFFFFF", 0xFFFFFFFFL)]
    [InlineData("2#1010", 10L)]
    public void TryParse_Integer_GivesValue(string text, long value)
    {
        AwlOperand.TryParse(text, out var operand, out _).Should().BeTrue();
        (operand!.Kind, operand.ConstantKind, operand.Integer).Should().Be((AwlOperandKind.Constant, AwlConstantKind.Integer, value));
    }

    [Fact]
    public void TryParse_OtherKinds_AreClassified()
    {
        Parse("1.5").Real.Should().Be(1.5);
        Parse("'AB'").Should().Match<AwlOperand>(o => o.ConstantKind == AwlConstantKind.Ascii && o.Name == "AB" && o.Integer == 0x4142);
        Parse("'A'").Integer.Should().Be(65);
        Parse("\"AB\"").Should().Match<AwlOperand>(o => o.ConstantKind == AwlConstantKind.String && o.Name == "AB");
        Parse("SBR6").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Symbol && o.Name == "SBR6");
        Parse("INT0").Kind.Should().Be(AwlOperandKind.Symbol);
        Parse("&AIW0").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Pointer && o.Area == MemoryArea.AI);
        Parse("T37").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Address && o.Area == MemoryArea.T && o.ByteOffset == 37);
        Parse("C1").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Address && o.Area == MemoryArea.C && o.ByteOffset == 1);
        Parse("&VB100").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Pointer && o.Area == MemoryArea.V && o.ByteOffset == 100);
        Parse("*VD10").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Indirect && o.Area == MemoryArea.V && o.ByteOffset == 10);
        Parse("*LD4").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Indirect && o.Area == MemoryArea.L);
        Parse("*AC1").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Indirect && o.Area == MemoryArea.AC && o.ByteOffset == 1);
        Parse("#count").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Local && o.Name == "count");
        Parse("OP_RX").Should().Match<AwlOperand>(o => o.Kind == AwlOperandKind.Symbol && o.Name == "OP_RX");
        Parse("INT_0").Kind.Should().Be(AwlOperandKind.Symbol);
        Parse("SBR_3").Kind.Should().Be(AwlOperandKind.Symbol);
    }

    [Theory]
    [InlineData("Z\u00e4hler", AwlOperandKind.Symbol, "Z\u00e4hler")]
    [InlineData("F\u00fcllstand_1", AwlOperandKind.Symbol, "F\u00fcllstand_1")]
    [InlineData("\u00c4nderung", AwlOperandKind.Symbol, "\u00c4nderung")]
    [InlineData("#Z\u00e4hler", AwlOperandKind.Local, "Z\u00e4hler")]
    public void TryParse_NameWithCodePageCharacters_IsANameNotABadAddress(string text, AwlOperandKind kind, string name)
    {
        AwlOperand.TryParse(text, out var operand, out var error).Should().BeTrue(error);

        (operand!.Kind, operand.Name).Should().Be((kind, name));
    }

    [Theory]
    [InlineData("M10.8", "outside 0-7")]
    [InlineData("*AC0", "AC1-AC3")]
    [InlineData("*VW10", "VD, LD or AC1-AC3")]
    [InlineData("&VW100", "address of a byte")]
    [InlineData("16#XY", "not a number")]
    [InlineData("'AB", "closing quote")]
    [InlineData("", "empty")]
    public void TryParse_Bad_GivesError(string text, string reason)
    {
        AwlOperand.TryParse(text, out _, out var error).Should().BeFalse();
        error.Should().Contain(reason);
    }

    private static AwlOperand Parse(string text) =>
        AwlOperand.TryParse(text, out var operand, out var error) ? operand : throw new InvalidOperationException(error);
}
