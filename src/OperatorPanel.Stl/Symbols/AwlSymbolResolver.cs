using System.Collections.Immutable;

namespace OperatorPanel.Stl.Symbols;

/// <summary>
/// Replaces the symbolic operands of a program (LD Always_On, MOVW +5, Setpoint) with the addresses a symbol table
/// gives them, so the checks, the merge and the interpreter see addresses; lines stay where they were. A symbol the
/// table does not hold is an error naming its line and the symbol. Block names (CALL's and ATCH's first operand) and
/// #locals are not symbols of the table.
/// </summary>
public static class AwlSymbolResolver
{
    public static (AwlProgram Program, ImmutableArray<AwlDiagnostic> Unknown) Resolve(AwlProgram program, AwlSymbolTable table)
    {
        ArgumentNullException.ThrowIfNull(program);
        ArgumentNullException.ThrowIfNull(table);
        var unknown = ImmutableArray.CreateBuilder<AwlDiagnostic>();
        var blocks = program.Blocks.Select(block => block with
        {
            Networks = [.. block.Networks.Select(network => network with
            {
                Instructions = [.. network.Instructions.Select(i => Resolve(i, table, unknown))],
            })],
        });
        return (new AwlProgram([.. blocks]), unknown.ToImmutable());
    }

    private static AwlInstruction Resolve(AwlInstruction instruction, AwlSymbolTable table, ImmutableArray<AwlDiagnostic>.Builder unknown)
    {
        var names = instruction.Mnemonic is "CALL" or "ATCH" ? 1 : 0;
        var operands = instruction.Operands.Select((text, index) =>
        {
            if (index < names || !AwlOperand.TryParse(text, out var operand, out _) || operand.Kind != AwlOperandKind.Symbol)
            {
                return text;
            }

            if (table.TryGetAddress(text, out var address))
            {
                return address;
            }

            unknown.Add(new AwlDiagnostic(instruction.Line, $"{instruction.Mnemonic}: symbol '{text}' is not in the symbol table"));
            return text;
        });
        return instruction with { Operands = [.. operands] };
    }
}
