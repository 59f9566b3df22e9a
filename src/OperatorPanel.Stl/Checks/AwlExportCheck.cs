using System.Collections.Immutable;

namespace OperatorPanel.Stl.Checks;

/// <summary>
/// What Micro/WIN's import refuses in the structure of a file, beyond each instruction (<see cref="AwlProgramCheck"/>):
/// a block header without its name, a CALL or ATCH to a block the file does not hold, a block number or name defined
/// twice (docs/awl-exports.md, "What Micro/WIN refuses"). And what it exports but cannot be checked: a password-protected
/// POU, exported without its code (<see cref="AwlBlock.IsPasswordProtected"/>; a warning).
/// </summary>
public static class AwlExportCheck
{
    public static AwlExportFindings Check(AwlProgram program)
    {
        ArgumentNullException.ThrowIfNull(program);
        var refusals = ImmutableArray.CreateBuilder<AwlDiagnostic>();
        var warnings = ImmutableArray.CreateBuilder<AwlDiagnostic>();
        var names = new Dictionary<string, AwlBlock>(StringComparer.OrdinalIgnoreCase);
        var numbers = new HashSet<(AwlBlockKind, int)>();
        foreach (var block in program.Blocks)
        {
            if (!block.HasName)
            {
                refusals.Add(Finding(AwlCheckIds.BlockHeaderWithoutName, block.StartLine,
                    $"the header of {block.NumberName} has no name: Micro/WIN imports {Keyword(block.Kind)} NAME:{block.NumberName} (as it exports, e.g. {Example(block)})"));
            }

            if (!numbers.Add((block.Kind, block.Number)))
            {
                refusals.Add(Finding(AwlCheckIds.BlockDefinedTwice, block.StartLine, $"{block.DefaultName} is defined twice in the file"));
            }
            else if (!names.TryAdd(block.Name, block))
            {
                refusals.Add(Finding(AwlCheckIds.BlockDefinedTwice, block.StartLine, $"block name {block.Name} is used twice in the file"));
            }

            if (block.IsPasswordProtected)
            {
                warnings.Add(Finding(AwlCheckIds.ProtectedBlock, block.StartLine,
                    $"{block.Name} ({block.NumberName}) is password-protected: Micro/WIN exports it without its code, so nothing of it can be checked or run here; export it unprotected to include it"));
            }
        }

        foreach (var block in program.Blocks)
        {
            foreach (var instruction in block.Instructions.Where(i => i.Mnemonic is "CALL" or "ATCH" && i.Operands.Length > 0))
            {
                var wanted = instruction.Mnemonic == "CALL" ? AwlBlockKind.Subroutine : AwlBlockKind.InterruptRoutine;
                if (!Resolves(program, instruction.Operands[0], wanted))
                {
                    refusals.Add(Finding(AwlCheckIds.BlockNotInFile, instruction.Line,
                        $"{instruction.Mnemonic} {instruction.Operands[0]}: the file has no {(wanted == AwlBlockKind.Subroutine ? "subroutine" : "interrupt routine")} of that name; Micro/WIN imports no {instruction.Mnemonic} to a block that is not there"));
                }
            }
        }

        return new AwlExportFindings(refusals.ToImmutable(), warnings.ToImmutable());
    }

    /// <summary>A block is named by its own name, its default name (SBR_3, INT_0) or the number exports write (SBR3, INT0).</summary>
    private static bool Resolves(AwlProgram program, string name, AwlBlockKind kind) =>
        program.Blocks.Any(b => b.Kind == kind
            && (string.Equals(b.Name, name, StringComparison.OrdinalIgnoreCase)
                || string.Equals(b.DefaultName, name, StringComparison.OrdinalIgnoreCase)
                || string.Equals(b.NumberName, name, StringComparison.OrdinalIgnoreCase)));

    private static string Keyword(AwlBlockKind kind) => kind switch
    {
        AwlBlockKind.OrganizationBlock => "ORGANIZATION_BLOCK",
        AwlBlockKind.Subroutine => "SUBROUTINE_BLOCK",
        AwlBlockKind.InterruptRoutine => "INTERRUPT_BLOCK",
    };

    private static string Example(AwlBlock block) =>
        $"{Keyword(block.Kind)} {(block.Kind == AwlBlockKind.OrganizationBlock ? "MAIN" : block.DefaultName)}:{block.NumberName}";

    private static AwlDiagnostic Finding(string id, int line, string message) => new(line, message) { Id = id };
}
