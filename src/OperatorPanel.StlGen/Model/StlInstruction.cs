using System.Collections.Immutable;

namespace OperatorPanel.StlGen.Model;

/// <summary>One STL instruction line: mnemonic, operands as Micro/WIN writes them, and an optional trailing comment.</summary>
public sealed record StlInstruction(string Mnemonic, ImmutableArray<string> Operands, string? Comment = null)
{
    public static StlInstruction Of(string mnemonic, params string[] operands) => new(mnemonic, [.. operands]);
}
