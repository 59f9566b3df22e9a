namespace OperatorPanel.Simulator.Stl;

/// <summary>One executable instruction: code, up to three resolved operands, an integer argument and its cost.</summary>
internal sealed class StlOp
{
    public required StlOpCode Code { get; init; }

    public StlLoc? A { get; set; }

    public StlLoc? B { get; set; }

    public StlLoc? C { get; set; }

    /// <summary>Jump target index, edge slot, compare relation, event number or port, by code.</summary>
    public int N { get; set; }

    /// <summary>Index of the block a CALL or ATCH names.</summary>
    public int Target { get; set; }

    /// <summary>Compare width in bytes (1, 2, 4).</summary>
    public int Width { get; init; }

    /// <summary>Estimated execution time with power flow, in ns (see <see cref="StlTiming"/>).</summary>
    public long Cost { get; set; }

    public StlParameter[] Parameters { get; set; } = [];

    public int Line { get; init; }

    public required string Mnemonic { get; init; }
}
