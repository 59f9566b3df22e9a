using System.Collections.Immutable;

namespace OperatorPanel.StlGen.Model;

/// <summary>
/// One POU: OB1, SBRn or INTn with the name Micro/WIN shows for it (the part before the colon in the .awl header;
/// CALL and ATCH name the block by it).
/// </summary>
public sealed record StlBlock(
    StlBlockKind Kind,
    string Name,
    int Number,
    string Title,
    ImmutableArray<string> Comments,
    ImmutableArray<StlNetwork> Networks)
{
    /// <summary>"OB1", "SBR63", "INT125".</summary>
    public string NumberText => Kind switch
    {
        StlBlockKind.Organization => $"OB{Number}",
        StlBlockKind.Subroutine => $"SBR{Number}",
        StlBlockKind.Interrupt => $"INT{Number}",
    };

    public int InstructionCount => Networks.Sum(n => n.Instructions.Length);
}
