using System.Globalization;
using OperatorPanel.StlGen.Model;

namespace OperatorPanel.StlGen.Emit;

/// <summary>
/// Writes a program in the .awl format Micro/WIN 4 exports and imports (/work/briefs/stl-dialect.md): blocks in the
/// order OB1, SBRs, INTs; networks "Network n // title"; mnemonic padded to 7 characters, operands joined by ", ".
/// Every instruction passes <see cref="EmittedInstructionCheck"/> first: the generator writes only what the table has.
/// </summary>
public static class AwlWriter
{
    private const int MnemonicWidth = 7;

    public static string Write(StlProgram program)
    {
        ArgumentNullException.ThrowIfNull(program);
        var w = new LineWriter();
        foreach (var block in program.Blocks.OrderBy(b => b.Kind))
        {
            var keyword = Keyword(block.Kind);
            w.Line($"{keyword} {block.Name}:{block.NumberText}");
            w.Line("TITLE=" + block.Title);
            foreach (var comment in block.Comments)
            {
                w.Line("// " + comment);
            }

            w.Line("BEGIN");
            var number = 1;
            foreach (var network in block.Networks)
            {
                WriteNetwork(w, network, number++, block.Kind);
            }

            w.Line("END_" + keyword);
        }

        return w.ToString();
    }

    /// <summary>"MOVB   16#09, SMB30"; a mnemonic of 7 or more characters is followed by one space.</summary>
    public static string FormatInstruction(StlInstruction instruction)
    {
        ArgumentNullException.ThrowIfNull(instruction);
        var line = instruction.Operands.IsEmpty
            ? instruction.Mnemonic
            : (instruction.Mnemonic.Length >= MnemonicWidth ? instruction.Mnemonic + " " : instruction.Mnemonic.PadRight(MnemonicWidth))
              + string.Join(", ", instruction.Operands);
        return instruction.Comment is null ? line : line + " // " + instruction.Comment;
    }

    private static void WriteNetwork(LineWriter w, StlNetwork network, int number, StlBlockKind block)
    {
        w.Line($"Network {number.ToString(CultureInfo.InvariantCulture)} // {network.Title}");
        foreach (var comment in network.Comments)
        {
            w.Line("// " + comment);
        }

        foreach (var instruction in network.Instructions)
        {
            EmittedInstructionCheck.Ensure(instruction, block);
            w.Line(FormatInstruction(instruction));
        }
    }

    private static string Keyword(StlBlockKind kind) => kind switch
    {
        StlBlockKind.Organization => "ORGANIZATION_BLOCK",
        StlBlockKind.Subroutine => "SUBROUTINE_BLOCK",
        StlBlockKind.Interrupt => "INTERRUPT_BLOCK",
    };
}
