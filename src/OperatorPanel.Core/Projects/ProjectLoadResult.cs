using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;

namespace OperatorPanel.Core.Projects;

/// <summary>What loading a project file gave: the project, or every problem found (never both).</summary>
public sealed record ProjectLoadResult
{
    /// <summary>At most this many problems are listed; a file with more gets one last entry saying so.</summary>
    public const int ProblemLimit = 100;

    private ProjectLoadResult(PanelProject? project, ImmutableArray<ProjectFileError> errors)
    {
        Project = project;
        Errors = errors;
    }

    public PanelProject? Project { get; }

    public ImmutableArray<ProjectFileError> Errors { get; }

    /// <summary>The loader stopped at <see cref="ProblemLimit"/>: the file has more problems than <see cref="Errors"/> lists.</summary>
    public bool ProblemsCut => Errors.Length > ProblemLimit;

    [MemberNotNullWhen(true, nameof(Project))]
    public bool Ok => Project is not null;

    public static ProjectLoadResult Success(PanelProject project) => new(project ?? throw new ArgumentNullException(nameof(project)), []);

    public static ProjectLoadResult Failure(ImmutableArray<ProjectFileError> errors)
    {
        if (errors.IsDefaultOrEmpty)
        {
            throw new ArgumentException("a failed load names at least one problem", nameof(errors));
        }

        return new ProjectLoadResult(null, errors);
    }
}
