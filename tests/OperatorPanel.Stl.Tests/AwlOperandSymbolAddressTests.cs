using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Stl.Tests;

/// <summary>NAME:ADDRESS operands, as Micro/WIN exports a symbol with its address (docs/awl-exports.md).</summary>
public sealed class AwlOperandSymbolAddressTests
{
    [Theory]
    [InlineData("P13a_Rot_Des:M2.0", AwlOperandKind.Address, MemoryArea.M, 2, 0, "P13a_Rot_Des")]
    [InlineData("BUFFER:VB60", AwlOperandKind.Address, MemoryArea.V, 60, null, "BUFFER")]
    [InlineData("#XORCODE:LB6", AwlOperandKind.Address, MemoryArea.L, 6, null, "#XORCODE")]
    [InlineData("&Buffer:VB100", AwlOperandKind.Pointer, MemoryArea.V, 100, null, "Buffer")]
    [InlineData("*Zeiger:VD10", AwlOperandKind.Indirect, MemoryArea.V, 10, null, "Zeiger")]
    [InlineData("Zähler_1:VW4", AwlOperandKind.Address, MemoryArea.V, 4, null, "Zähler_1")]
    public void TryParse_SymbolWithAddress_IsTheAddressAndKeepsTheName(string text, AwlOperandKind kind, MemoryArea area, int offset, int? bit, string name)
    {
        AwlOperand.TryParse(text, out var operand, out var error).Should().BeTrue(error);

        operand!.Kind.Should().Be(kind);
        operand.Area.Should().Be(area);
        operand.ByteOffset.Should().Be(offset);
        operand.Bit.Should().Be(bit);
        operand.SymbolName.Should().Be(name);
        operand.Text.Should().Be(text);
    }

    [Theory]
    [InlineData("Rot Des:M2.0", "the symbol before ':' is written with letters, digits and _")]
    [InlineData("1abc:M2.0", "the symbol before ':' is written with letters, digits and _")]
    [InlineData("Rot_Des:M2.8", "after the symbol 'Rot_Des:' an address is expected")]
    [InlineData("Rot_Des:100", "after the symbol 'Rot_Des:' an address is expected")]
    [InlineData("FCS:SBR1", "after the symbol 'FCS:' an address is expected")]
    public void TryParse_BadSymbolWithAddress_GivesError(string text, string reason)
    {
        AwlOperand.TryParse(text, out _, out var error).Should().BeFalse();

        error.Should().Contain(reason);
    }

    [Fact]
    public void TryParse_StringConstantWithColon_IsAString()
    {
        AwlOperand.TryParse("'A:'", out var operand, out _).Should().BeTrue();

        operand!.ConstantKind.Should().Be(AwlConstantKind.Ascii);
        operand.SymbolName.Should().BeNull();
    }
}
