using System.Collections.Immutable;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Stl.Instructions;

namespace OperatorPanel.Stl.Checks;

/// <summary>
/// Refuses, line by line, what Micro/WIN refuses in a program for one CPU, by the instruction table: unknown mnemonics,
/// MEND/RET/RETI written out, compare relations STL does not have, instructions in the wrong kind of block, events the
/// CPU lacks, S/R with N = 0, operands of a kind the instruction does not take. The interpreter's loader, the merge and
/// <c>opanel stl run</c> all read a program through it.
/// </summary>
public static class AwlProgramCheck
{
    public static ImmutableArray<AwlDiagnostic> Check(AwlProgram program, CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(program);
        ArgumentNullException.ThrowIfNull(cpu);
        var found = ImmutableArray.CreateBuilder<AwlDiagnostic>();
        foreach (var block in program.Blocks)
        {
            foreach (var instruction in block.Instructions)
            {
                found.AddRange(Check(instruction, block, cpu));
            }
        }

        return found.ToImmutable();
    }

    /// <summary>The refusals of one instruction written in <paramref name="block"/>.</summary>
    public static IEnumerable<AwlDiagnostic> Check(AwlInstruction instruction, AwlBlock block, CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(instruction);
        ArgumentNullException.ThrowIfNull(block);
        ArgumentNullException.ThrowIfNull(cpu);
        var line = instruction.Line;
        var mnemonic = instruction.Mnemonic;
        if (!StlInstructionTable.TryGet(mnemonic, out var spec))
        {
            yield return Unknown(instruction);
            yield break;
        }

        if (spec.Placement == StlPlacement.None)
        {
            yield return Refuse(AwlCheckIds.ImplicitBlockEnd, line, $"{mnemonic} is not written in STL: Micro/WIN ends every block itself (MEND in OB1, RET in subroutines, RETI in interrupt routines); remove the line, or use the conditional {Conditional(mnemonic)}");
            yield break;
        }

        if (PlacementRefusal(spec, block) is { } placement)
        {
            yield return placement with { Line = line };
        }

        if (spec.Firmware == StlFirmware.Version2 && cpu.Revision == CpuRevision.Early)
        {
            yield return Refuse(AwlCheckIds.NeedsFirmware2, line, $"{mnemonic} needs CPU firmware 2.0 or later; the {cpu.DisplayName} does not have it");
        }

        foreach (var refusal in StlInstructionOperandsCheck.Check(instruction, spec, block, cpu))
        {
            yield return refusal;
        }
    }

    internal static AwlDiagnostic Refuse(string id, int line, string message) => new(line, message) { Id = id };

    private static AwlDiagnostic Unknown(AwlInstruction instruction)
    {
        var mnemonic = instruction.Mnemonic;
        foreach (var form in (string[])["LD", "A", "O"])
        {
            foreach (var width in "BWDRS")
            {
                var prefix = $"{form}{width}";
                if (mnemonic.Length > prefix.Length && mnemonic.StartsWith(prefix, StringComparison.Ordinal)
                    && mnemonic[prefix.Length..].All(c => c is '=' or '<' or '>' or '!'))
                {
                    return Refuse(AwlCheckIds.CompareRelation, instruction.Line, $"{mnemonic}: '{mnemonic[prefix.Length..]}' is not an STL compare relation; STL writes {prefix}=, {prefix}<>, {prefix}<, {prefix}<=, {prefix}>, {prefix}>= (== is LAD's way of writing =)");
                }
            }
        }

        return Refuse(AwlCheckIds.UnknownInstruction, instruction.Line, $"{mnemonic} is not an S7-200 STL instruction (see docs/stl-instructions.md)");
    }

    private static string Conditional(string mnemonic) => mnemonic switch
    {
        "RET" => "CRET",
        "RETI" => "CRETI",
        _ => "END",
    };

    private static AwlDiagnostic? PlacementRefusal(StlInstructionSpec spec, AwlBlock block)
    {
        var here = block.Kind switch
        {
            AwlBlockKind.OrganizationBlock => StlPlacement.Main,
            AwlBlockKind.Subroutine => StlPlacement.Subroutine,
            AwlBlockKind.InterruptRoutine => StlPlacement.InterruptRoutine,
        };
        if ((spec.Placement & here) != 0)
        {
            return null;
        }

        return here == StlPlacement.InterruptRoutine && spec.Placement == (StlPlacement.Main | StlPlacement.Subroutine)
            ? Refuse(AwlCheckIds.NotInInterruptRoutine, 0, $"{spec.Mnemonic} cannot be used in an interrupt routine ({block.Name}); DISI, ENI, HDEF and END may not be used there")
            : Refuse(AwlCheckIds.WrongBlockKind, 0, $"{spec.Mnemonic} can only be used in {Where(spec.Placement)}, not in {block.Name} ({block.DefaultName})");
    }

    private static string Where(StlPlacement placement)
    {
        (StlPlacement Flag, string Words)[] blocks =
            [(StlPlacement.Main, "the main program (OB1)"), (StlPlacement.Subroutine, "a subroutine"), (StlPlacement.InterruptRoutine, "an interrupt routine")];
        return string.Join(" or ", blocks.Where(b => placement.HasFlag(b.Flag)).Select(b => b.Words));
    }
}
