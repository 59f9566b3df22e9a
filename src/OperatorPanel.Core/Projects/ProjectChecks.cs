using System.Collections.Immutable;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// What is still wrong with a project that loads: settings that contradict each other though each is valid alone. The
/// panel opens such a project (it reads and writes as any other, and refuses what cannot work when it is tried), so these
/// are not load problems; <c>opanel project check</c> lists them as problems (exit 1), the panel names the first when it
/// opens the project, and the wizard's Finish refuses them. In the file's order, each at its place:
/// <list type="bullet">
/// <item>a compact Freeport station with STOP allowed (<see cref="CompactStop"/>), at <c>$.stations[N]</c>;</item>
/// <item>a writable tag whose every write the write rules refuse (<see cref="WriteRules.TagProblem"/>): it shares bytes
/// with a read-only tag, or lies in the handler's own V bytes, at <c>$.stations[N].tags[M]</c>.</item>
/// </list>
/// </summary>
public static class ProjectChecks
{
    public static ImmutableArray<ProjectFileError> Problems(PanelProject project)
    {
        ArgumentNullException.ThrowIfNull(project);
        var stopProblems = CompactStop.Problems(project).ToDictionary(p => p.Location);
        var problems = ImmutableArray.CreateBuilder<ProjectFileError>();
        for (var s = 0; s < project.Stations.Length; s++)
        {
            var station = project.Stations[s];
            var path = JsonPath.Index("$.stations", s);
            if (stopProblems.TryGetValue(path, out var stop))
            {
                problems.Add(stop);
            }

            for (var t = 0; t < station.Tags.Length; t++)
            {
                if (WriteRules.TagProblem(station.Tags[t], station) is { } message)
                {
                    problems.Add(new ProjectFileError(JsonPath.Index($"{path}.tags", t), message));
                }
            }
        }

        return problems.ToImmutable();
    }
}
