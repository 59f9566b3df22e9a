using System.Collections.Immutable;

namespace OperatorPanel.Core.Projects;

/// <summary>Collects every problem of one load, so the user sees all of them at once and not just the first.</summary>
internal sealed class ProjectProblems
{
    private readonly List<ProjectFileError> _items = [];

    public int Count => _items.Count;

    public void Add(string location, string message) => _items.Add(new ProjectFileError(location, message));

    public ImmutableArray<ProjectFileError> ToImmutable() => [.. _items];
}
