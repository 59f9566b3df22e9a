namespace OperatorPanel.StlGen.Model;

/// <summary>The program organisation units of an S7-200 program, in the order a .awl file lists them.</summary>
public enum StlBlockKind
{
    /// <summary>OB1, the main program.</summary>
    Organization,

    /// <summary>SBRn, a subroutine.</summary>
    Subroutine,

    /// <summary>INTn, an interrupt routine.</summary>
    Interrupt,
}
