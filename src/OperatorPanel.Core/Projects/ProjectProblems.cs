using System.Collections.Immutable;
using System.Globalization;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Collects every problem of one load, so the user sees all of them at once and not just the first; up to
/// <see cref="ProjectLoadResult.ProblemLimit"/>, then one line says there are more and the readers stop (a file of a
/// million broken entries gave four million problems and took a minute to load).
/// </summary>
internal sealed class ProjectProblems
{
    private readonly List<ProjectFileError> _items = [];

    public int Count => _items.Count;

    /// <summary>The list is full: readers stop walking arrays, since nothing more would be shown.</summary>
    public bool IsFull => _items.Count > ProjectLoadResult.ProblemLimit;

    public void Add(string location, string message)
    {
        if (_items.Count < ProjectLoadResult.ProblemLimit)
        {
            _items.Add(new ProjectFileError(location, message));
        }
        else if (_items.Count == ProjectLoadResult.ProblemLimit)
        {
            _items.Add(new ProjectFileError("file", string.Create(CultureInfo.InvariantCulture,
                $"more than {ProjectLoadResult.ProblemLimit} problems; the rest are not listed: correct these and load the file again")));
        }
    }

    public ImmutableArray<ProjectFileError> ToImmutable() => [.. _items];
}
