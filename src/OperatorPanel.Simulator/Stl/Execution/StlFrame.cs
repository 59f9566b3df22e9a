namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>One running block on the call stack: where it is, the caller's logic stack, its L memory base, and the CALL that entered it.</summary>
internal struct StlFrame
{
    public StlBlock Block;
    public int Pc;
    public uint SavedStack;
    public int LBase;
    public StlOp? Call;
}
