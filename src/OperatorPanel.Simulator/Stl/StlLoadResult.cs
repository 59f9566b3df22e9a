using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Stl;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The loaded program, or null when any diagnostic was found: a program with errors does not run. Warnings (what the
/// simulator will not do, by line) come with a program too.
/// </summary>
public sealed record StlLoadResult(StlProgram? Program, ImmutableArray<AwlDiagnostic> Diagnostics)
{
    public ImmutableArray<AwlDiagnostic> Warnings { get; init; } = [];

    [MemberNotNullWhen(true, nameof(Program))]
    public bool Succeeded => Program is not null;
}
