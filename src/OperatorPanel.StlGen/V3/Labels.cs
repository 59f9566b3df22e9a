namespace OperatorPanel.StlGen.V3;

/// <summary>Jump labels of OP_PANEL (LBL 0-255, local to the block), each number used once.</summary>
internal static class Labels
{
    public const int Silence = 1;
    public const int ErrorReply = 2;
    public const int RequestStart = 3;
    public const int CheckLoop = 4;
    public const int CheckNext = 6;
    public const int Dispatch = 7;
    public const int Identify = 11;
    public const int Read = 12;
    public const int Write = 13;
    public const int WriteBits = 14;
    public const int DefineList = 15;
    public const int Stop = 18;
    public const int ItemCheck = 20;
    public const int MoveData = 33;
    public const int DefineItem = 37;
    public const int DefineStore = 38;
    public const int ReadList = 40;
    public const int Gather = 41;
    public const int WholeHead = 46;
    public const int Compare = 47;
    public const int CompareDone = 44;

    /// <summary>60-63: the comparison's groups 0-3.</summary>
    public const int Quarter = 60;
    public const int Changes = 48;
    public const int ChangesLoop = 49;
    public const int ReplyInR = 50;

    /// <summary>OP_PANEL's phase groups (Builder.Resumes): the list's loops, the heavy steps.</summary>
    public const int LoopPhases = 70;
    public const int HeavyPhases = 71;

    /// <summary>Send what is ready, then back to OB1 (the block's end; elsewhere CRET ends the scan's part).</summary>
    public const int Publish = 98;
}
