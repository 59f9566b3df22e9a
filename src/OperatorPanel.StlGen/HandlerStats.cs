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

    /// <summary>The READ CHANGES copy area, the last <see cref="CopyBytes"/> of the V bytes (0 = none).</summary>
    public int CopyBytes { get; init; }

    /// <summary>The work bytes READ CHANGES and STOP added (per-list copy state, comparison, STOP state).</summary>
    public int ChangesWorkBytes { get; init; }

    /// <summary>Whether the handler carries 07 STOP.</summary>
    public bool StopEnabled { get; init; }

    /// <summary>2 (hex frames) or 3 (binary frames).</summary>
    public int Protocol { get; init; } = 2;

    /// <summary>Version 3: the compact handler (no list, no STOP).</summary>
    public bool Compact { get; init; }

    /// <summary>The instructions and networks, the estimated program size and the CPU's program memory beside it.</summary>
    public required HandlerSize Size { get; init; }

    /// <summary>"VB8072-VB8191", or "none".</summary>
    public string CopyRange => CopyBytes == 0 ? "none" : $"VB{LastVByte - CopyBytes + 1}-VB{LastVByte}";

    /// <summary>"VB7900-VB8191".</summary>
    public string VRange => $"VB{FirstVByte}-VB{LastVByte}";
}

/// <summary>One block the handler adds: "OP_RX", "INT125", what it does.</summary>
public sealed record HandlerBlock(string Name, string NumberText, string Purpose);
