using System.Collections.Immutable;

namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// One SIMATIC STL instruction of the S7-200 (CPU 221-226) as docs/stl-instructions.md lists it: mnemonic, operands
/// in STL order, where it may be written, which CPUs have it, the SMB1 bits it affects, what sets ENO = 0, and the
/// manual page it comes from.
/// </summary>
public sealed record StlInstructionSpec(string Mnemonic, StlInstructionGroup Group, ImmutableArray<StlOperandSpec> Operands)
{
    public StlPlacement Placement { get; init; } = StlPlacement.Anywhere;

    public StlFirmware Firmware { get; init; } = StlFirmware.All;

    public StlStatusBits StatusBits { get; init; }

    /// <summary>The manual's "Error conditions that set ENO = 0", e.g. "SM4.3, 0006"; empty when it lists none.</summary>
    public string EnoErrors { get; init; } = string.Empty;

    /// <summary>Edition and page the entry comes from, or "unsourced: ..." where no page was found.</summary>
    public required string Source { get; init; }

    /// <summary>CALL only: actual parameters may follow the fixed operands, one per formal of the callee.</summary>
    public bool TakesParameters { get; init; }

    /// <summary>Index of the operand that counts the elements of widened operands (N, LEN), or -1.</summary>
    public int CountIndex
    {
        get
        {
            if (Operands.All(o => o.Extent == StlExtent.One))
            {
                return -1;
            }

            for (var i = 0; i < Operands.Length; i++)
            {
                if (Operands[i].Name is "N" or "LEN")
                {
                    return i;
                }
            }

            return -1;
        }
    }

    public bool IsCompare => Group == StlInstructionGroup.Compare;
}
