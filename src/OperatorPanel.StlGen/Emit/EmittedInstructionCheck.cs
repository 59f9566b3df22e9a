using OperatorPanel.Stl;
using OperatorPanel.Stl.Instructions;
using OperatorPanel.StlGen.Model;

namespace OperatorPanel.StlGen.Emit;

/// <summary>
/// The emitter's guard: every instruction the generator writes must be in the Core <see cref="StlInstructionTable"/>
/// with operands of the kinds the table allows, in a block it may be written in. Anything else is a generator bug
/// and fails loudly instead of producing text Micro/WIN would refuse (as SHLW once did).
/// </summary>
public static class EmittedInstructionCheck
{
    /// <summary>Throws <see cref="InvalidOperationException"/> naming the instruction when it is not valid STL.</summary>
    public static void Ensure(StlInstruction instruction, StlBlockKind block)
    {
        if (Problem(instruction, block) is { } problem)
        {
            throw new InvalidOperationException($"generator bug: '{AwlWriter.FormatInstruction(instruction)}' in a {block} block: {problem}");
        }
    }

    /// <summary>Why <paramref name="instruction"/> is not valid STL in a block of kind <paramref name="block"/>; null when it is.</summary>
    public static string? Problem(StlInstruction instruction, StlBlockKind block)
    {
        ArgumentNullException.ThrowIfNull(instruction);
        if (!StlInstructionTable.TryGet(instruction.Mnemonic, out var spec))
        {
            return $"{instruction.Mnemonic} is not an S7-200 STL instruction";
        }

        var here = block switch
        {
            StlBlockKind.Organization => StlPlacement.Main,
            StlBlockKind.Subroutine => StlPlacement.Subroutine,
            StlBlockKind.Interrupt => StlPlacement.InterruptRoutine,
        };
        if ((spec.Placement & here) == 0)
        {
            return $"{spec.Mnemonic} may not be written in this block";
        }

        var operands = instruction.Operands;
        if (spec.TakesParameters ? operands.Length < spec.Operands.Length : operands.Length != spec.Operands.Length)
        {
            return $"{spec.Mnemonic} takes {spec.Operands.Length} operand(s), {operands.Length} given";
        }

        for (var i = 0; i < spec.Operands.Length; i++)
        {
            if (!AwlOperand.TryParse(operands[i], out var operand, out var error))
            {
                return error;
            }

            if (StlOperandMatch.Check(spec.Operands[i], operand) is { } refusal)
            {
                return refusal.Reason;
            }
        }

        return null;
    }
}
