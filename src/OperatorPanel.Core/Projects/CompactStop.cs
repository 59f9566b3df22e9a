using System.Collections.Immutable;
using System.Globalization;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// The one rule for a station's "compact" and "allowStop": the compact handler has no STOP (docs/protocol.md section 6),
/// so a station asking for both would get a handler without the STOP its user allowed, silently. The panel reads and
/// writes such a station as any other, so the project still loads; <c>opanel project check</c> reports it, generate,
/// simulate, Generate PLC code and the demo line refuse it (STL031), and the wizard's link page flags it, each with this
/// sentence in its own words for the two settings (<see cref="CompactStopWords"/>).
/// </summary>
public static class CompactStop
{
    /// <summary>True when a handler is asked to be compact and to carry STOP: the two cannot both hold.</summary>
    public static bool Contradicts(bool compact, bool allowStop) => compact && allowStop;

    /// <summary>What is wrong and the two ways out, <paramref name="who"/> first ("Filler (station 2)").</summary>
    public static string Describe(string who, CompactStopWords words)
    {
        ArgumentNullException.ThrowIfNull(who);
        ArgumentNullException.ThrowIfNull(words);
        return $"{who} has {words.Compact} and {words.AllowStop}, but a compact handler has no STOP: it would be generated "
            + $"without the STOP that is allowed; {words.CompactOff} for the full handler with STOP, or {words.AllowStopOff} for "
            + "the compact handler without it";
    }

    /// <summary>"Filler (station 2)": how the messages name a station.</summary>
    public static string Who(ProjectStation station)
    {
        ArgumentNullException.ThrowIfNull(station);
        return string.Create(CultureInfo.InvariantCulture, $"{station.Name} (station {station.Address.Address})");
    }

    /// <summary>
    /// Every station of <paramref name="project"/> (a Freeport one: a PPI station has no handler) with both settings, at
    /// its place in the file (<c>$.stations[0]</c>): what <c>opanel project check</c> lists after a clean load.
    /// </summary>
    public static ImmutableArray<ProjectFileError> Problems(PanelProject project)
    {
        ArgumentNullException.ThrowIfNull(project);
        return [.. project.Stations
            .Select((station, index) => (station, index))
            .Where(s => s.station.Link.Protocol == LinkProtocol.Freeport && Contradicts(s.station.Compact, s.station.AllowStop))
            .Select(s => new ProjectFileError(JsonPath.Index("$.stations", s.index), Describe(Who(s.station), CompactStopWords.File)))];
    }
}
