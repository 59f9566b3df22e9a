using OperatorPanel.StlGen.Emit;
using OperatorPanel.StlGen.Model;

namespace OperatorPanel.StlGen.Tests.Emit;

public sealed class EmittedInstructionCheckTests
{
    [Theory]
    [InlineData("SHLW", new[] { "AC0", "3" }, "SHLW is not an S7-200 STL instruction")]
    [InlineData("MOVW", new[] { "VB0", "VW2" }, "'VB0' is a byte; IN is a WORD")]
    [InlineData("MOVB", new[] { "VB0" }, "takes 2 operand(s), 1 given")]
    [InlineData("LDB==", new[] { "VB0", "5" }, "LDB== is not an S7-200 STL instruction")]
    [InlineData("RETI", new string[0], "RETI may not be written in this block")]
    public void Problem_InstructionOutsideTheTable_IsNamed(string mnemonic, string[] operands, string expected)
    {
        EmittedInstructionCheck.Problem(StlInstruction.Of(mnemonic, operands), StlBlockKind.Interrupt).Should().Contain(expected);
    }

    [Theory]
    [InlineData("SLW", new[] { "AC0", "3" })]
    [InlineData("MOVD", new[] { "&VB100", "AC1" })]
    [InlineData("ATCH", new[] { "OP_RX", "23" })]
    [InlineData("CRETI", new string[0])]
    public void Problem_InstructionOfTheTable_IsNone(string mnemonic, string[] operands)
    {
        EmittedInstructionCheck.Problem(StlInstruction.Of(mnemonic, operands), StlBlockKind.Interrupt).Should().BeNull();
    }

    [Fact]
    public void Write_ProgramWithMnemonicOutsideTheTable_FailsLoudly()
    {
        var network = new StlNetwork("shift", [], [StlInstruction.Of("SHLB", "VB0", "1")]);
        var program = new StlProgram([new StlBlock(StlBlockKind.Organization, "MAIN", 1, "Main", [], [network])]);

        var write = () => AwlWriter.Write(program);

        write.Should().Throw<InvalidOperationException>().WithMessage("generator bug: 'SHLB   VB0, 1'*SHLB is not an S7-200 STL instruction*");
    }
}
