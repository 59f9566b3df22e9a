namespace OperatorPanel.Stl.Instructions;

/// <summary>Operand kinds written as the manual writes them for one data type: "VW, IW, QW, MW, SW, SMW, LW, T, C, AC, *VD, *LD, *AC, constant".</summary>
public static class StlOperandKindsText
{
    private static readonly (StlOperandKinds Kind, string Prefix)[] Order =
    [
        (StlOperandKinds.I, "I"), (StlOperandKinds.Q, "Q"), (StlOperandKinds.V, "V"), (StlOperandKinds.M, "M"),
        (StlOperandKinds.SM, "SM"), (StlOperandKinds.S, "S"), (StlOperandKinds.L, "L"), (StlOperandKinds.T, "T"),
        (StlOperandKinds.C, "C"), (StlOperandKinds.HC, "HC"), (StlOperandKinds.AI, "AI"), (StlOperandKinds.AQ, "AQ"),
        (StlOperandKinds.AC, "AC"), (StlOperandKinds.IndirectV, "*VD"), (StlOperandKinds.IndirectL, "*LD"),
        (StlOperandKinds.IndirectAc, "*AC"), (StlOperandKinds.AddressOf, "&VB"), (StlOperandKinds.Pou, "POU"),
        (StlOperandKinds.Constant, "constant"),
    ];

    /// <summary>The kinds of <paramref name="spec"/>, memory areas with the width letter of its type (V in a WORD: VW).</summary>
    public static string Describe(StlOperandSpec spec)
    {
        ArgumentNullException.ThrowIfNull(spec);
        var width = spec.Bytes switch { 1 => "B", 2 => "W", 4 => "D", _ => string.Empty };
        const StlOperandKinds sized = StlOperandKinds.I | StlOperandKinds.Q | StlOperandKinds.V | StlOperandKinds.M
            | StlOperandKinds.SM | StlOperandKinds.S | StlOperandKinds.L | StlOperandKinds.AI | StlOperandKinds.AQ;
        var words = Order.Where(o => (spec.Kinds & o.Kind) != 0).Select(o => (sized & o.Kind) != 0 ? o.Prefix + width : o.Prefix);
        return string.Join(", ", words);
    }
}
