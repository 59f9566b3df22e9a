using OperatorPanel.Stl;

namespace OperatorPanel.Stl.Tests;

public sealed class AwlParserTests
{
    private const string Export =
        "ORGANIZATION_BLOCK MAIN:OB1\r\n" +
        "TITLE=Main program\r\n" +
        "// program comment\r\n" +
        "BEGIN\r\n" +
        "Network 1 // Initialise\r\n" +
        "// first scan only\r\n" +
        "LD     SM0.1\r\n" +
        "MOVB   16#09, SMB30      // Freeport 9600\r\n" +
        "\r\n" +
        "// a comment between instructions\r\n" +
        "CALL   OP_INIT, VB10, VW20, &VB100\r\n" +
        "Network 2\r\n" +
        "ATCH   OP_RX, 23\r\n" +
        "END_ORGANIZATION_BLOCK\r\n" +
        "SUBROUTINE_BLOCK OP_INIT:SBR10\r\n" +
        "TITLE=Init\r\n" +
        "VAR_INPUT\r\n" +
        "count:BYTE;\t// how many\r\n" +
        "END_VAR\r\n" +
        "VAR_OUTPUT\r\n" +
        "result:WORD;\r\n" +
        "END_VAR\r\n" +
        "VAR\r\n" +
        "ptr:DWORD;\r\n" +
        "END_VAR\r\n" +
        "BEGIN\r\n" +
        "Network 1 // Copy\r\n" +
        "LD     SM0.0\r\n" +
        "MOVW   #result, VW0\r\n" +
        "END_SUBROUTINE_BLOCK\r\n" +
        "INTERRUPT_BLOCK OP_RX:INT100\r\n" +
        "BEGIN\r\n" +
        "Network 1\r\n" +
        "LDB=   VB10, 16#01\n" +
        "END_INTERRUPT_BLOCK\r\n";

    [Fact]
    public void Parse_MicroWinExport_ReadsBlocksNetworksAndVariables()
    {
        var result = AwlParser.Parse(Export);

        result.Diagnostics.Should().BeEmpty();
        var blocks = result.Program.Blocks;
        blocks.Select(b => (b.Kind, b.Name, b.Number)).Should().Equal(
            (AwlBlockKind.OrganizationBlock, "MAIN", 1), (AwlBlockKind.Subroutine, "OP_INIT", 10), (AwlBlockKind.InterruptRoutine, "OP_RX", 100));
        blocks[0].Title.Should().Be("Main program");
        blocks[0].Comments.Should().Equal("program comment");
        blocks[0].Networks.Select(n => (n.Number, n.Title)).Should().Equal((1, "Initialise"), (2, ""));
        blocks[0].Networks[0].Comments.Should().Equal("first scan only");
        var move = blocks[0].Networks[0].Instructions[1];
        (move.Mnemonic, move.Line, move.Comment).Should().Be(("MOVB", 8, "Freeport 9600"));
        move.Operands.Should().Equal("16#09", "SMB30");
        blocks[0].Networks[0].Instructions[2].Operands.Should().Equal("OP_INIT", "VB10", "VW20", "&VB100");
        blocks[1].Variables.Select(v => (v.Name, v.Type, v.Section, v.Comment)).Should().Equal(
            ("count", "BYTE", AwlVariableSection.Input, "how many"),
            ("result", "WORD", AwlVariableSection.Output, ""),
            ("ptr", "DWORD", AwlVariableSection.Temp, ""));
        (blocks[1].StartLine, blocks[1].EndLine).Should().Be((15, 30));
        result.Program.Find("SBR_10").Should().BeSameAs(blocks[1]);
        result.Program.Find("op_rx").Should().BeSameAs(blocks[2]);
    }

    [Fact]
    public void Parse_MegabyteLineOutsideABlock_QuotesTheLineShortened()
    {
        var result = AwlParser.Parse(new string('9', 1 << 20) + "\n" + Export);

        var diagnostic = result.Diagnostics.Should().ContainSingle().Subject;
        diagnostic.Line.Should().Be(1);
        diagnostic.Message.Should().Be("'" + new string('9', 39) + "...' is outside any block; expected ORGANIZATION_BLOCK, SUBROUTINE_BLOCK or INTERRUPT_BLOCK");
    }

    [Fact]
    public void Parse_CarriageReturnInsideALine_IsNamedWithItsLine()
    {
        var result = AwlParser.Parse(Export.Replace("// a comment between instructions", "// a comment\rLD I0.0", StringComparison.Ordinal));

        result.Diagnostics.Should().ContainSingle().Which.ToString().Should().Be(
            "line 10: a carriage return (16#0D) inside the line; a line ends with CR LF or LF, and text after a lone CR would be misread");
    }

    [Fact]
    public void Parse_NulByteOutsideABlock_ShowsItAsItsCode()
    {
        var result = AwlParser.Parse("\01\n" + Export);

        result.Diagnostics.Should().ContainSingle().Which.Message.Should().StartWith("'<16#00>1' is outside any block");
    }

    [Theory]
    [InlineData("\u00EF\u00BB\u00BF")]
    [InlineData("\uFEFF")]
    public void Parse_FileSavedAsUtf8WithByteOrderMark_IsNamedAsSuchAtLineOne(string byteOrderMark)
    {
        var result = AwlParser.Parse(byteOrderMark + Export);

        result.Diagnostics.Should().ContainSingle().Which.ToString().Should().Be(
            "line 1: the file starts with a UTF-8 byte order mark (EF BB BF); Micro/WIN exports in the Windows code page without one: save the file as ANSI");
        result.Program.Blocks.Should().HaveCount(3);
    }

    [Fact]
    public void Parse_BadText_ReportsEachProblemWithItsLine()
    {
        var text = "GARBAGE\nORGANIZATION_BLOCK MAIN:OB1\nVAR\nx BYTE\nEND_VAR\nBEGIN\nNetwork x\nLD I0.0\nEND_SUBROUTINE_BLOCK\nSUBROUTINE_BLOCK S:SBR1\nBEGIN\n";

        var result = AwlParser.Parse(text);

        result.Succeeded.Should().BeFalse();
        result.Diagnostics.Select(d => d.Line).Should().Equal(1, 4, 7, 9, 12);
        result.Diagnostics[0].ToString().Should().StartWith("line 1: 'GARBAGE' is outside any block");
        result.Program.Blocks.Should().HaveCount(2);
    }
}
