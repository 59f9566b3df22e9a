namespace OperatorPanel.Stl;

/// <summary>The three kinds of program organisation unit in a Micro/WIN .awl export.</summary>
public enum AwlBlockKind
{
    /// <summary>ORGANIZATION_BLOCK name:OB1, the main program.</summary>
    OrganizationBlock,

    /// <summary>SUBROUTINE_BLOCK name:SBRn.</summary>
    Subroutine,

    /// <summary>INTERRUPT_BLOCK name:INTn.</summary>
    InterruptRoutine,
}
