using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Memory;

/// <summary>Copies of a project with one station's memory cells replaced (projects are immutable records).</summary>
internal static class ProjectEdits
{
    public static PanelProject WithTags(PanelProject project, Station station, ImmutableArray<ProjectTag> tags) =>
        project with
        {
            Stations = [.. project.Stations.Select(s => s.Address == station ? s with { Tags = tags } : s)],
        };

    /// <summary>True when <paramref name="symbol"/> is already an input, output or cell of the station (compared ignoring case).</summary>
    public static bool SymbolTaken(ProjectStation station, string symbol) =>
        station.Inputs.Select(i => i.Symbol)
            .Concat(station.Outputs.Select(o => o.Symbol))
            .Concat(station.Tags.Select(t => t.Symbol))
            .Contains(symbol, StringComparer.OrdinalIgnoreCase);
}
