namespace OperatorPanel.Stl.Instructions;

/// <summary>The program organisation units an instruction may be written in.</summary>
[Flags]
public enum StlPlacement
{
    /// <summary>Written nowhere: Micro/WIN adds MEND, RET and RETI at the end of each block itself.</summary>
    None = 0,
    Main = 1 << 0,
    Subroutine = 1 << 1,
    InterruptRoutine = 1 << 2,
    Anywhere = Main | Subroutine | InterruptRoutine,
}
