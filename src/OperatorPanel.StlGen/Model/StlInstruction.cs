using System.Collections.Immutable;

namespace OperatorPanel.StlGen.Model;

/// <summary>
/// One STL instruction line: mnemonic, operands as Micro/WIN writes them, and an optional trailing comment. Equal when
/// mnemonic, operands (in order) and comment are equal.
/// </summary>
public sealed record StlInstruction(string Mnemonic, ImmutableArray<string> Operands, string? Comment = null)
{
    public static StlInstruction Of(string mnemonic, params string[] operands) => new(mnemonic, [.. operands]);

    public bool Equals(StlInstruction? other) =>
        other is not null && Mnemonic == other.Mnemonic && Comment == other.Comment && Operands.SequenceEqual(other.Operands);

    public override int GetHashCode() => HashCode.Combine(Mnemonic, Comment, Operands.Length);
}
