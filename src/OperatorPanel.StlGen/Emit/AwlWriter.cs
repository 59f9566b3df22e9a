using System.Globalization;
using OperatorPanel.Stl.Instructions;
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
            w.Line(FormatInstruction(SignedAsExported(instruction)));
        }
    }

    /// <summary>
    /// Decimal constants of word and double-word operands with their sign, as Micro/WIN writes them in its exports
    /// (<c>MOVW +100, VW100</c>, <c>TON T37, +50</c>, <c>MOVD +0, VD140</c>; byte constants stay unsigned: docs/awl-exports.md).
    /// No page says whether Micro/WIN's import also takes them unsigned, so the generator writes the form Micro/WIN
    /// itself produces.
    /// </summary>
    internal static StlInstruction SignedAsExported(StlInstruction instruction)
    {
        if (!StlInstructionTable.TryGet(instruction.Mnemonic, out var spec))
        {
            return instruction;
        }

        var operands = instruction.Operands.ToBuilder();
        for (var i = 0; i < Math.Min(operands.Count, spec.Operands.Length); i++)
        {
            var type = spec.Operands[i].Type;
            long? limit = type is StlDataType.Word or StlDataType.Int ? short.MaxValue
                : type is StlDataType.DWord or StlDataType.DInt ? int.MaxValue
                : null;
            if (limit is not null && operands[i].Length is > 0 and <= 10 && operands[i].All(char.IsAsciiDigit)
                && long.Parse(operands[i], CultureInfo.InvariantCulture) <= limit)
            {
                operands[i] = "+" + operands[i];
            }
        }

        return instruction with { Operands = operands.ToImmutable() };
    }

    private static string Keyword(StlBlockKind kind) => kind switch
    {
        StlBlockKind.Organization => "ORGANIZATION_BLOCK",
        StlBlockKind.Subroutine => "SUBROUTINE_BLOCK",
        StlBlockKind.Interrupt => "INTERRUPT_BLOCK",
    };
}
