using System.Collections.Immutable;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// One production line's panel configuration, stored as one <c>.opproj</c> file: the PLC stations on the line and
/// how the panel refreshes them (seed 000 §7: the five wizard steps CPU, I/O symbols, memory cells, alarm texts, link).
/// </summary>
/// <param name="Name">Shown in the panel's title bar; may be empty.</param>
/// <param name="Refresh">Continuous or triggered refresh, for every station of the line.</param>
/// <param name="Stations">One or more PLCs; each checks its own addresses against its own CPU.</param>
/// <remarks>
/// <see cref="History"/> and <see cref="AlarmSound"/> ("history" and "alarmSound" in the file, both optional) are init
/// properties so the projects built in code keep their shape.
/// </remarks>
public sealed record PanelProject(string Name, RefreshSettings Refresh, ImmutableArray<ProjectStation> Stations)
{
    /// <summary>What the historian records of this project and for how long (docs/historian.md).</summary>
    public HistorySettings History { get; init; } = HistorySettings.Default;

    /// <summary>The alarm sound of each class repeats until the alarm is acknowledged or silenced; false keeps the panel quiet.</summary>
    public bool AlarmSound { get; init; } = true;
}
