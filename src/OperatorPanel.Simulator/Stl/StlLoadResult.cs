using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Stl;

namespace OperatorPanel.Simulator.Stl;

/// <summary>The loaded program, or null when any diagnostic was found: a program with errors does not run.</summary>
public sealed record StlLoadResult(StlProgram? Program, ImmutableArray<AwlDiagnostic> Diagnostics)
{
    [MemberNotNullWhen(true, nameof(Program))]
    public bool Succeeded => Program is not null;
}
