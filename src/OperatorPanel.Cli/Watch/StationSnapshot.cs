namespace OperatorPanel.Cli.Watch;

/// <summary>One station in a <see cref="WatchSnapshot"/>: its link state and counters, lamps, tags and active alarms.</summary>
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
    IReadOnlyList<AlarmRow> Alarms);
