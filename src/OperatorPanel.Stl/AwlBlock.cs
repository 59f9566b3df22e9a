using System.Collections.Immutable;

namespace OperatorPanel.Stl;

/// <summary>
/// One program organisation unit: <c>SUBROUTINE_BLOCK OP_INIT:SBR10</c> has name OP_INIT and number 10.
/// Lines are 1-based lines of the source text (the block line and its END_ line).
/// </summary>
public sealed record AwlBlock(
    AwlBlockKind Kind,
    string Name,
    int Number,
    string Title,
    ImmutableArray<string> Comments,
    ImmutableArray<AwlVariable> Variables,
    ImmutableArray<AwlNetwork> Networks,
    int StartLine,
    int EndLine)
{
    /// <summary>The default name Micro/WIN gives a block of this kind and number: OB1, SBR_3, INT_0.</summary>
    public string DefaultName => Kind switch
    {
        AwlBlockKind.OrganizationBlock => $"OB{Number}",
        AwlBlockKind.Subroutine => $"SBR_{Number}",
        AwlBlockKind.InterruptRoutine => $"INT_{Number}",
    };

    /// <summary>The numeric reference exports write in CALL and ATCH: SBR6, INT0 (OB1 for the main program).</summary>
    public string NumberName => Kind switch
    {
        AwlBlockKind.OrganizationBlock => $"OB{Number}",
        AwlBlockKind.Subroutine => $"SBR{Number}",
        AwlBlockKind.InterruptRoutine => $"INT{Number}",
    };

    public IEnumerable<AwlInstruction> Instructions => Networks.SelectMany(n => n.Instructions);
}
