namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// What <see cref="DemoProcess"/> needs from a simulated CPU: the memory it drives, whether the program runs, where a
/// scan ends, and which outputs the panel took over. Both models serve it (<see cref="ReferencePlc"/> and the STL
/// station), so <c>--demo</c> shows the same bottle filler whichever model answers the panel.
/// </summary>
public interface IDemoPlc
{
    /// <summary>I, Q, M, V and SM; the demo sets inputs and flags and reads outputs here.</summary>
    PlcMemory Memory { get; }

    OperatingMode Mode { get; }

    /// <summary>One demo scan of <paramref name="milliseconds"/> ended (inputs written, outputs set).</summary>
    void CompleteScan(ushort milliseconds);

    /// <summary>True when the panel has written output Qn.b; the demo program then leaves it alone.</summary>
    bool IsOwnedByPanel(int offset, int bit);
}
