using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Recording;

namespace OperatorPanel.Cli.History;

/// <summary>
/// The TAG arguments of <c>history</c> and <c>trend</c> against the project: a symbol ("TankLevel"), a station's symbol
/// ("Filler.TankLevel"), or an address ("VW150", "Filler.VW150"); symbols ignore case. A name two stations share needs
/// its station. None given: every recorded value of the project.
/// </summary>
internal static class TagArguments
{
    public static bool TryResolve(PanelProject project, IReadOnlyList<string> arguments, [NotNullWhen(true)] out List<NamedTag>? tags, [NotNullWhen(false)] out string? error)
    {
        var recorded = RecordedTag.Of(project with { History = project.History with { Enabled = true } });
        var all = recorded.Select(t => new NamedTag(project.Stations.First(s => s.Address == t.Station).Name, t)).ToList();
        tags = [];
        error = null;
        if (arguments.Count == 0)
        {
            tags = all;
            return true;
        }

        foreach (var argument in arguments)
        {
            var (stationName, name) = Split(argument);
            var candidates = all.Where(t => (stationName is null || string.Equals(t.StationName, stationName, StringComparison.OrdinalIgnoreCase))
                && (string.Equals(t.Tag.Symbol, name, StringComparison.OrdinalIgnoreCase) || (PlcAddress.TryParse(name, out var a, out _) && a == t.Tag.Address))).ToList();
            switch (candidates.Count)
            {
                case 1:
                    tags.Add(candidates[0]);
                    break;
                case 0:
                    error = $"'{argument}': no recorded input, output or tag of that name or address in the project (a tag with \"record\": false is not recorded)";
                    return false;
                default:
                    error = $"'{argument}' is on {string.Join(" and ", candidates.Select(c => c.StationName))}: write STATION.{name}";
                    return false;
            }
        }

        return true;
    }

    private static (string? Station, string Name) Split(string argument)
    {
        var dot = argument.IndexOf('.', StringComparison.Ordinal);
        // "I0.0" and "M2.1" carry a dot of their own: only a dot before a name or an address splits off a station.
        if (dot > 0 && !PlcAddress.TryParse(argument, out _, out _))
        {
            return (argument[..dot], argument[(dot + 1)..]);
        }

        return (null, argument);
    }
}

/// <summary>A recorded value with its station's name, as <c>history</c> and <c>trend</c> print it ("Filler.TankLevel").</summary>
internal sealed record NamedTag(string StationName, RecordedTag Tag)
{
    public string Name => $"{StationName}.{Tag.Symbol}";
}
