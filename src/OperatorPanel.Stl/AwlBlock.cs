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

    /// <summary>False for a header without a name (<c>ORGANIZATION_BLOCK OB1</c>): Micro/WIN writes <c>NAME:OB1</c>.</summary>
    public bool HasName { get; init; } = true;

    /// <summary>
    /// True for a password-protected POU as Micro/WIN exports it: one network titled <see cref="ProtectedTitle"/> and no
    /// instruction (the Siemens libraries' MBUS_INIT, MBUS_SLAVE and the motion wizard's blocks in Sebaasu/xk335b-scada
    /// 1_Transporte/4_Traduccion_Ladder.awl), or BEGIN with no network at all (inferred before that export was seen;
    /// Micro/WIN writes at least <c>Network 1</c> for an empty block). docs/awl-exports.md, "A protected POU".
    /// </summary>
    public bool IsPasswordProtected => Networks.IsEmpty
        || (Networks.Length == 1 && Networks[0].Instructions.IsEmpty
            && Networks[0].Title.Contains(ProtectedTitle, StringComparison.OrdinalIgnoreCase));

    /// <summary>The network title Micro/WIN exports in place of a protected POU's body (without its final full stop).</summary>
    public const string ProtectedTitle = "This POU is password-protected";
}
