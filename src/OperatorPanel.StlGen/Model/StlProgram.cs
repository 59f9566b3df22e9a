using System.Collections.Immutable;

namespace OperatorPanel.StlGen.Model;

/// <summary>A whole program block: OB1, then the subroutines, then the interrupt routines (the .awl order).</summary>
public sealed record StlProgram(ImmutableArray<StlBlock> Blocks)
{
    public int InstructionCount => Blocks.Sum(b => b.InstructionCount);
}
