using OperatorPanel.Core.Cpu;
using OperatorPanel.Stl.Instructions;

namespace OperatorPanel.Stl.Checks;

/// <summary>The operands of one instruction against its table entry and the CPU: count, kinds, ranges, events, ports, memory on the CPU (<see cref="AwlCpuRanges"/>).</summary>
internal static class StlInstructionOperandsCheck
{
    public static IEnumerable<AwlDiagnostic> Check(AwlInstruction instruction, StlInstructionSpec spec, AwlBlock block, CpuProfile cpu)
    {
        var line = instruction.Line;
        var operands = instruction.Operands;
        var fixedCount = spec.Operands.Length;
        if (spec.TakesParameters ? operands.Length < fixedCount : operands.Length != fixedCount)
        {
            yield return AwlProgramCheck.Refuse(AwlCheckIds.OperandCount, line, $"{spec.Mnemonic} takes {(spec.TakesParameters ? "at least " : string.Empty)}{fixedCount} operand(s) ({string.Join(", ", spec.Operands.Select(o => o.Name))}), found {operands.Length}");
            yield break;
        }

        for (var i = 0; i < fixedCount; i++)
        {
            if (Check(spec, spec.Operands[i], operands[i], block, cpu) is { } refusal)
            {
                yield return AwlProgramCheck.Refuse(refusal.Id, line, $"{spec.Mnemonic}: {refusal.Message}");
            }
        }
    }

    private static (string Id, string Message)? Check(StlInstructionSpec spec, StlOperandSpec operandSpec, string text, AwlBlock block, CpuProfile cpu)
    {
        if (!AwlOperand.TryParse(text, out var operand, out var parseError))
        {
            return (AwlCheckIds.OperandKind, parseError);
        }

        if (operandSpec.Kinds == StlOperandKinds.Pou)
        {
            return operand.Kind == AwlOperandKind.Symbol ? null
                : (AwlCheckIds.OperandKind, $"'{text}' is not a {(operandSpec.Type == StlDataType.Subroutine ? "subroutine (SBR_n, SBRn or its name)" : "interrupt routine (INT_n, INTn or its name)")}");
        }

        var local = operand.Kind == AwlOperandKind.Local
            ? block.Variables.FirstOrDefault(v => string.Equals(v.Name, operand.Name, StringComparison.Ordinal))
            : null;
        if (StlOperandMatch.Check(operandSpec, operand, local) is { } refusal)
        {
            var zeroCount = refusal.Kind == StlRefusalKind.OutOfRange && operandSpec.Min == 1 && operand.Integer == 0
                && spec.Mnemonic is "S" or "R" or "SI" or "RI";
            return zeroCount ? (AwlCheckIds.CountIsZero, $"N = 0 sets or resets nothing; N is 1-255")
                : (refusal.Kind == StlRefusalKind.Kind ? AwlCheckIds.OperandKind : AwlCheckIds.OutOfRange, refusal.Reason);
        }

        return operand is { Kind: AwlOperandKind.Constant, ConstantKind: AwlConstantKind.Integer } ? CheckCpuNumber(operandSpec, operand, cpu)
            : AwlCpuRanges.Check(operand, operandSpec.IsWritten, cpu);
    }

    private static (string Id, string Message)? CheckCpuNumber(StlOperandSpec spec, AwlOperand operand, CpuProfile cpu)
    {
        if (spec.Type == StlDataType.Event && !StlInterruptEvents.IsOnCpu(cpu, operand.Integer))
        {
            return (AwlCheckIds.EventNotOnCpu, $"the {cpu.Name} has no interrupt event {operand.Integer} (it has events {StlInterruptEvents.RangeText(cpu)})");
        }

        return spec.Type == StlDataType.Port && operand.Integer >= cpu.CommunicationPorts
            ? (AwlCheckIds.OutOfRange, $"the {cpu.Name} has no port {operand.Integer} (ports 0-{cpu.CommunicationPorts - 1})")
            : null;
    }
}
