using OperatorPanel.Core.Protocol;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// Jump labels of OP_PANEL's checks and replies (LBL 0-255, local to the block; SlicePart, FrameCheckPart, ReadPart,
/// WritePart, ChangesPart and ChangesOfListsPart keep theirs): all in the one subroutine, each number used once.
/// </summary>
internal static class HandlerLabels
{
    public const int Silence = 1;
    public const int ErrorReply = 2;
    public const int Finish = 3;
    public const int Identify = 11;
    public const int Read = 12;
    public const int Write = 13;
    public const int WriteBit = 14;
    public const int DefineList = 15;
    public const int ReadList = 16;
    public const int ReadChanges = 17;
    public const int Stop = 18;
    public const int ReadChangesOfLists = 19;

    /// <summary>22-27: reply with error code 02-07 (docs/protocol-v2.md section 3).</summary>
    public const int ErrorBase = 20;
    public const int CheckItems = 30;
    public const int ReadItemsChecked = 41;
    public const int BuildItems = 40;
    public const int Writable = 50;
    public const int WriteBitExecute = 52;
    public const int DefineItemsChecked = 60;

    public static int Error(ProtocolError error) => ErrorBase + (byte)error;

    public static string Of(int label) => HandlerContext.Dec(label);
}
