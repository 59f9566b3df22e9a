namespace OperatorPanel.Cli.Watch;

/// <summary>
/// One station in a <see cref="WatchSnapshot"/>: its link state and counters, lamps, tags, and the alarms that are active
/// or unknown (<see cref="AlarmsUnknown"/> counts the latter: a station not read has unknown alarms, not none).
/// </summary>
internal sealed record StationSnapshot(
    string Name,
    int Station,
    string Cpu,
    string Port,
    string State,
    string? LastError,
    int? NextTryInSeconds,
    string? Handler,
    LinkView Link,
    IReadOnlyList<LampByte> Inputs,
    IReadOnlyList<LampByte> Outputs,
    IReadOnlyList<TagRow> Tags,
    IReadOnlyList<AlarmRow> Alarms)
{
    public int AlarmsUnknown => Alarms.Count(a => a.State == AlarmRow.Unknown);

    public int AlarmsActive => Alarms.Count(a => a.State == AlarmRow.Active);

    /// <summary>The project's alarm count for this station, for "3 of 8 flags not read".</summary>
    public int AlarmsDefined { get; init; }
}
