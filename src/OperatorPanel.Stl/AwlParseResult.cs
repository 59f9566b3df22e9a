using System.Collections.Immutable;

namespace OperatorPanel.Stl;

/// <summary>What <see cref="AwlParser.Parse"/> read: the blocks it understood and a diagnostic for every line it did not.</summary>
public sealed record AwlParseResult(AwlProgram Program, ImmutableArray<AwlDiagnostic> Diagnostics)
{
    public bool Succeeded => Diagnostics.IsEmpty;
}
