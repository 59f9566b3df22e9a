using System.Collections.Immutable;

namespace OperatorPanel.StlGen;

/// <summary>
/// What the generated handler reserves and how big it is, known without running it: the V bytes, the blocks and the
/// interrupt events (what a merge must check against the user's program), and the instruction count.
/// </summary>
public sealed record HandlerStats(
    int FirstVByte,
    int LastVByte,
    int Instructions,
    int Port,
    ImmutableArray<int> InterruptEvents,
    ImmutableArray<HandlerBlock> Blocks)
{
    public int VBytes => LastVByte - FirstVByte + 1;

    /// <summary>"VB7900-VB8191".</summary>
    public string VRange => $"VB{FirstVByte}-VB{LastVByte}";
}

/// <summary>One block the handler adds: "OP_RX", "INT125", what it does.</summary>
public sealed record HandlerBlock(string Name, string NumberText, string Purpose);
