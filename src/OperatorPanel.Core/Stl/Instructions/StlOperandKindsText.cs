namespace OperatorPanel.Core.Stl.Instructions;

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
        var words = Order.Where(o => (spec.Kinds & o.Kind) != 0).Select(o => o.Kind switch
        {
            StlOperandKinds.I or StlOperandKinds.Q or StlOperandKinds.V or StlOperandKinds.M or StlOperandKinds.SM
                or StlOperandKinds.S or StlOperandKinds.L or StlOperandKinds.AI or StlOperandKinds.AQ => o.Prefix + width,
            _ => o.Prefix,
        });
        return string.Join(", ", words);
    }
}
