using OperatorPanel.Stl;
using OperatorPanel.Stl.Instructions;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// How each operand of an instruction is used, read from the Core <see cref="StlInstructionTable"/>: whether it is
/// written (STL writes OUT = OUT op IN, so OUT is read and written), and how many elements it covers (a count widens
/// BMB IN and OUT, S bits, FILL OUT, ATH/HTA digits, SHRB S_BIT; a TODR buffer is 8 bytes). CALL parameters are written
/// where the callee declares them VAR_IN_OUT or VAR_OUTPUT. A mnemonic the table lacks only reads its operands.
/// </summary>
internal static class InstructionOperands
{
    /// <summary>Every operand of <paramref name="instruction"/> that parses as an operand; CALL parameters via the callee's variable table.</summary>
    public static IEnumerable<OperandUse> Uses(AwlInstruction instruction, AwlProgram program)
    {
        var operands = instruction.Operands;
        var spec = StlInstructionTable.TryGet(instruction.Mnemonic, out var found) ? found : null;
        var calleeOutputs = spec?.TakesParameters == true ? CallOutputs(instruction, program) : [];
        var countIndex = spec?.CountIndex ?? -1;
        long? count = null;
        if (countIndex >= 0 && countIndex < operands.Length && AwlOperand.TryParse(operands[countIndex], out var n, out _)
            && n is { Kind: AwlOperandKind.Constant, ConstantKind: AwlConstantKind.Integer })
        {
            count = n.Integer;
        }

        for (var i = 0; i < operands.Length; i++)
        {
            if (!AwlOperand.TryParse(operands[i], out var operand, out _))
            {
                continue;
            }

            var slot = spec is not null && i < spec.Operands.Length ? spec.Operands[i] : null;
            var widened = slot is not null && slot.Extent != StlExtent.One && countIndex >= 0;
            var elements = slot is null ? 1 : Elements(slot, count);
            var isWritten = slot?.IsWritten == true || (i > 0 && calleeOutputs.Contains(i - 1));
            yield return new OperandUse(instruction, i, operand, isWritten, elements, widened && count is null);
        }
    }

    /// <summary>Elements covered; a widened operand whose count is not a constant counts as its first element only.</summary>
    private static long Elements(StlOperandSpec slot, long? count) => slot.Extent switch
    {
        StlExtent.One => slot.Length,
        StlExtent.Count => count ?? 1,
        StlExtent.HalfCount => count is { } n ? (n + 1) / 2 : 1,
        StlExtent.AbsoluteCount => count is { } n ? Math.Abs(n) : 1,
    };

    /// <summary>Parameter positions (0-based, after the block name) bound to VAR_IN_OUT or VAR_OUTPUT of the called block.</summary>
    private static HashSet<int> CallOutputs(AwlInstruction call, AwlProgram program)
    {
        var callee = call.Operands.Length > 0 ? program.Find(call.Operands[0]) : null;
        var parameters = callee?.Variables.Where(v => v.Section != AwlVariableSection.Temp).OrderBy(v => v.Section).ToList() ?? [];
        return [.. parameters.Select((v, i) => (v, i)).Where(p => p.v.Section != AwlVariableSection.Input).Select(p => p.i)];
    }
}
