using OperatorPanel.StlGen.Emit;
using OperatorPanel.StlGen.Model;
using OperatorPanel.StlGen.Tests.Golden;

namespace OperatorPanel.StlGen.Tests.Emit;

public sealed class AwlWriterTests
{
    [Theory]
    [InlineData("LD", new[] { "SM0.1" }, "LD     SM0.1")]
    [InlineData("MOVB", new[] { "16#09", "SMB30" }, "MOVB   16#09, SMB30")]
    [InlineData("LDB=", new[] { "VB10", "16#01" }, "LDB=   VB10, 16#01")]
    [InlineData("ENI", new string[0], "ENI")]
    [InlineData("LONGMNE", new[] { "A" }, "LONGMNE A")]
    public void FormatInstruction_PadsMnemonicToSeven_JoinsOperandsWithCommaSpace(string mnemonic, string[] operands, string expected) =>
        AwlWriter.FormatInstruction(StlInstruction.Of(mnemonic, operands)).Should().Be(expected);

    [Theory]
    [InlineData("MOVW", new[] { "0", "SMW90" }, "MOVW   +0, SMW90")]
    [InlineData("MOVD", new[] { "0", "VD140" }, "MOVD   +0, VD140")]
    [InlineData("-I", new[] { "6", "AC3" }, "-I     +6, AC3")]
    [InlineData("LDW>", new[] { "AC3", "0" }, "LDW>   AC3, +0")]
    [InlineData("FOR", new[] { "AC0", "1", "VW10" }, "FOR    AC0, +1, VW10")]
    [InlineData("MOVB", new[] { "0", "VB0" }, "MOVB   0, VB0")]
    [InlineData("LDB=", new[] { "VB10", "7" }, "LDB=   VB10, 7")]
    [InlineData("SLW", new[] { "VW20", "3" }, "SLW    VW20, 3")]
    [InlineData("MOVW", new[] { "16#FFFF", "VW0" }, "MOVW   16#FFFF, VW0")]
    [InlineData("MOVW", new[] { "-1", "VW0" }, "MOVW   -1, VW0")]
    [InlineData("MOVW", new[] { "40000", "VW0" }, "MOVW   40000, VW0")]
    [InlineData("MOVD", new[] { "&VB100", "AC1" }, "MOVD   &VB100, AC1")]
    public void SignedAsExported_WordAndDoubleWordDecimals_GetTheirSignAsMicroWinExportsThem(string mnemonic, string[] operands, string expected) =>
        AwlWriter.FormatInstruction(AwlWriter.SignedAsExported(StlInstruction.Of(mnemonic, operands))).Should().Be(expected);

    [Theory]
    [MemberData(nameof(HandlerGoldenTests.Cases), MemberType = typeof(HandlerGoldenTests))]
    public void Write_Handler_IsAsciiWithCrlfAfterEveryLineAndNoBom(string name)
    {
        var text = HandlerGenerator.Generate(HandlerGoldenTests.OptionsFor(name)).AwlText;

        text.Should().MatchRegex("^[\\x20-\\x7E\\r\\n]*$");
        text.Should().EndWith("\r\n");
        text.Replace("\r\n", string.Empty, StringComparison.Ordinal).Should().NotContain("\n").And.NotContain("\r");
        text.Should().StartWith("ORGANIZATION_BLOCK MAIN:OB1\r\n");
    }

    [Fact]
    public void Write_Handler_ListsBlocksInMicroWinOrder()
    {
        var lines = HandlerGenerator.Generate(HandlerGoldenTests.Cpu224Port0Station2).AwlText.Split("\r\n");

        lines.Where(l => l.EndsWith("_BLOCK", StringComparison.Ordinal) || l.Contains("_BLOCK ", StringComparison.Ordinal))
            .Should().Equal(
                "ORGANIZATION_BLOCK MAIN:OB1", "END_ORGANIZATION_BLOCK",
                "SUBROUTINE_BLOCK OP_PANEL:SBR63", "END_SUBROUTINE_BLOCK",
                "INTERRUPT_BLOCK OP_RX:INT125", "END_INTERRUPT_BLOCK",
                "INTERRUPT_BLOCK OP_DELAY:INT126", "END_INTERRUPT_BLOCK",
                "INTERRUPT_BLOCK OP_TX:INT127", "END_INTERRUPT_BLOCK");
    }

    [Fact]
    public void Write_Handler_NextAndLblStandInNetworksOfTheirOwn()
    {
        var program = HandlerGenerator.Generate(HandlerGoldenTests.Cpu224Port0Station2).Program!;

        var networks = program.Blocks.SelectMany(b => b.Networks).ToList();
        networks.Where(n => n.Instructions.Any(i => i.Mnemonic is "NEXT" or "LBL")).Should().OnlyContain(n => n.Instructions.Length == 1);
        networks.Should().OnlyContain(n => n.Title.Length > 0 && n.Comments.Length > 0 || n.Instructions.Length == 1);
    }

    [Fact]
    public void Write_NonAsciiComment_Throws()
    {
        var program = new StlProgram(
            [new StlBlock(StlBlockKind.Organization, "MAIN", 1, "T\u00e9st", [], [])]);

        var write = () => AwlWriter.Write(program);

        write.Should().Throw<ArgumentException>();
    }
}
