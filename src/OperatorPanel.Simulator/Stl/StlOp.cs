using OperatorPanel.Simulator.Stl.Operations;

namespace OperatorPanel.Simulator.Stl;

/// <summary>One executable instruction: its row of the instruction table, up to three resolved operands, an integer argument and its cost.</summary>
internal sealed class StlOp
{
    public required StlOperation Operation { get; init; }

    public StlOpCode Code => Operation.Code;

    public string Mnemonic => Operation.Mnemonic;

    public StlLoc? A { get; set; }

    public StlLoc? B { get; set; }

    public StlLoc? C { get; set; }

    /// <summary>Jump target index, edge slot, compare relation, event number or port, by code.</summary>
    public int N { get; set; }

    /// <summary>Index of the block a CALL or ATCH names.</summary>
    public int Target { get; set; }

    /// <summary>Compare width in bytes (1, 2, 4).</summary>
    public int Width { get; init; }

    /// <summary>Execution time with power flow, in ns: the row's time plus the parameter and indirect-operand adders.</summary>
    public long Cost { get; set; }

    public StlParameter[] Parameters { get; set; } = [];

    public int Line { get; init; }
}
