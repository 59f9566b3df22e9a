using System.Globalization;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// How the panel's historian records a project ("history" in the project file; docs/historian.md). Every I/O symbol and
/// tag is recorded on change unless a tag says <c>"record": false</c>; a numeric tag's change is recorded only when it moves
/// by more than its deadband (the tag's own <see cref="ProjectTag.Deadband"/>, or <see cref="DeadbandPercent"/> of the
/// value last recorded), and every <see cref="SamplePeriod"/> the value is recorded anyway, so a flat line shows as one.
/// </summary>
/// <param name="Enabled">False: nothing of this project is recorded (the alarm journal and the audit still are).</param>
/// <param name="DeadbandPercent">Default deadband of numeric tags: percent of the value last recorded, 0-100; 0 records every change.</param>
/// <param name="SamplePeriod">The slow periodic sample of every recorded value, 1 s - 24 h.</param>
/// <param name="RetentionDays">Records older than this are deleted, 1-3650 days.</param>
/// <param name="MaxSizeMb">When the database holds more than this, the oldest records are deleted first, 10-100000 MB.</param>
public sealed record HistorySettings(bool Enabled, double DeadbandPercent, TimeSpan SamplePeriod, int RetentionDays, int MaxSizeMb)
{
    public const double MaxDeadbandPercent = 100;
    public const int MinSamplePeriodS = 1;
    public const int MaxSamplePeriodS = 24 * 3600;
    public const int MaxRetentionDays = 3650;
    public const int MinSizeMb = 10;
    public const int MaxSizeMbLimit = 100_000;

    /// <summary>
    /// Recording on, 0.5 % deadband, a sample every 10 minutes, a year kept, at most 1 GB: the defaults that keep 2000
    /// tags changing every second under 100 MB a day (docs/historian.md, "Load").
    /// </summary>
    public static HistorySettings Default { get; } = new(true, 0.5, TimeSpan.FromMinutes(10), 365, 1024);

    /// <summary>"0.5 % deadband, sample every 10 min, kept 365 days or 1024 MB".</summary>
    public override string ToString() => string.Create(
        CultureInfo.InvariantCulture,
        $"{(Enabled ? string.Empty : "off; ")}{DeadbandPercent:0.###} % deadband, sample every {SamplePeriod.TotalSeconds:0} s, kept {RetentionDays} days or {MaxSizeMb} MB");
}
