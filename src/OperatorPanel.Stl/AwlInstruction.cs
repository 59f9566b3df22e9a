using System.Collections.Immutable;

namespace OperatorPanel.Stl;

/// <summary>One STL instruction line: mnemonic (upper case) and operand texts as written, without the separating ", ".</summary>
public sealed record AwlInstruction(string Mnemonic, ImmutableArray<string> Operands, string Comment, int Line);
