using System.Collections.Immutable;

namespace OperatorPanel.Stl;

/// <summary>The blocks of one .awl file in file order (OB1, subroutines, interrupt routines).</summary>
public sealed record AwlProgram(ImmutableArray<AwlBlock> Blocks)
{
    public AwlBlock? MainBlock => Blocks.FirstOrDefault(b => b.Kind == AwlBlockKind.OrganizationBlock);

    /// <summary>The block called <paramref name="name"/> (its own name, its default SBR_n / INT_n name or SBRn / INTn, case-insensitive).</summary>
    public AwlBlock? Find(string name) =>
        Blocks.FirstOrDefault(b => string.Equals(b.Name, name, StringComparison.OrdinalIgnoreCase))
        ?? Blocks.FirstOrDefault(b => string.Equals(b.DefaultName, name, StringComparison.OrdinalIgnoreCase))
        ?? Blocks.FirstOrDefault(b => string.Equals(b.NumberName, name, StringComparison.OrdinalIgnoreCase));
}
